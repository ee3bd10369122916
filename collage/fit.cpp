#include "collage/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "collage/distance.h"
#include "collage/initialise.h"
#include "collage/optimise.h"
#include "collage/refine.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::collage {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxMaps = 32;

std::vector<double> to_vector(const std::vector<AffineMap>& maps) {
  std::vector<double> x;
  for (const auto& f : maps)
    for (double k : f.coefficients()) x.push_back(k);
  return x;
}

std::vector<AffineMap> to_maps(std::span<const double> x) {
  std::vector<AffineMap> maps;
  for (std::size_t i = 0; i + 6 <= x.size(); i += 6)
    maps.push_back({x[i], x[i + 1], x[i + 2], x[i + 3], x[i + 4], x[i + 5]});
  return maps;
}

// Pixels of the canvas margin needed to reach `extent` plane units beyond the square, at most
// one square's worth (`size`).
int margin_pixels(double extent, int size, bool& clipped) {
  if (!(extent > 0)) return 0;
  const double pixels = std::ceil(extent * size) + 1;
  if (pixels > size) {
    clipped = true;
    return size;
  }
  return static_cast<int>(pixels);
}

}  // namespace

CollageReport assess(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "assess: the target must be a non-empty square CV_8UC1 working raster");
  validate(ifs, "assess");
  const int size = target.cols;
  CollageReport r;
  r.pixel = 1.0 / size;
  r.contraction = ifs.contraction();
  r.collage_distance = collage_distance(target, ifs.maps);
  r.lower_bound = r.collage_distance / (1 + r.contraction);
  r.upper_bound = r.contraction < 1 ? r.collage_distance / (1 - r.contraction)
                                    : std::numeric_limits<double>::infinity();
  r.collage = collage_raster(target, ifs.maps);
  r.collage_iou = iou(target, r.collage);

  // Render A on the target's grid, grown (by whole pixels, so the grids coincide) to hold the
  // attractor's bounding box: a part of A outside the square still counts in h and IoU.
  const Box bounds = attractor_bounds(ifs, options.seed);
  const int left = margin_pixels(-bounds.x0, size, r.clipped);
  const int right = margin_pixels(bounds.x1 - 1, size, r.clipped);
  const int bottom = margin_pixels(-bounds.y0, size, r.clipped);
  const int top = margin_pixels(bounds.y1 - 1, size, r.clipped);
  const cv::Size canvas_size(size + left + right, size + top + bottom);
  RenderOptions render;
  render.view = Box{-static_cast<double>(left) / size, -static_cast<double>(bottom) / size,
                    1 + static_cast<double>(right) / size, 1 + static_cast<double>(top) / size};
  render.quality = options.quality;
  render.seed = options.seed;
  render.threads = options.threads;
  const cv::Mat canvas_a = render_attractor(ifs, canvas_size, render);
  const cv::Rect square(left, top, size, size);
  r.attractor = canvas_a(square).clone();

  cv::Mat canvas_l(canvas_size, CV_8UC1, cv::Scalar(0));
  target.copyTo(canvas_l(square));
  if (cv::countNonZero(canvas_a) == 0) {
    r.hausdorff = std::numeric_limits<double>::infinity();
    r.iou = 0;
  } else {
    r.hausdorff = hausdorff(canvas_l, canvas_a) / size;
    r.iou = iou(canvas_l, canvas_a);
  }
  return r;
}

FitResult fit(const cv::Mat& target, const FitOptions& options) {
  if (options.maps < 1 || options.maps > kMaxMaps)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("-n: the number of maps must be in 1..{} (got {})", kMaxMaps, options.maps));
  if (options.restarts < 0 || options.max_evaluations < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("fit: restarts must be ≥ 0 and max_evaluations ≥ 1 (got {} and {})",
                            options.restarts, options.max_evaluations));
  if (!(options.max_seconds >= 0))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--max-seconds: must be ≥ 0 (got {})", options.max_seconds));
  const auto start = Clock::now();
  const CollageObjective objective(target, options.objective);
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };

  const int runs = options.restarts + 1;
  FitResult result;
  double best_objective = std::numeric_limits<double>::infinity();
  double best_iou = -1;
  for (int run = 0; run < runs; ++run) {
    options.cancel.check("fit");
    const long evaluations_left = options.max_evaluations - result.evaluations;
    if (evaluations_left < 2) break;
    if (options.max_seconds > 0 && seconds_since_start() >= options.max_seconds) {
      result.time_capped = true;
      break;
    }
    InitOptions init;
    if (run > 0) {
      init.split = Split::kmeans_plus_plus;
      init.seed = stream_seed(options.seed, static_cast<std::uint64_t>(run));
    }
    const auto start_maps = initial_maps(target, options.maps, init);

    // This run's share of what is left of the evaluations and of the time.
    const long run_evaluations = evaluations_left / (runs - run);
    const auto run_deadline =
        options.max_seconds > 0
            ? Clock::now() +
                  std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                      (options.max_seconds - seconds_since_start()) / (runs - run)))
            : Clock::time_point::max();
    CmaesOptions cmaes;
    cmaes.sigma = run == 0 ? 0.03 : 0.05;
    cmaes.max_evaluations = run_evaluations;
    cmaes.deadline = run_deadline;
    cmaes.seed = stream_seed(options.seed ^ 0x636f6c6c616765ULL, static_cast<std::uint64_t>(run));
    cmaes.threads = options.threads;
    cmaes.cancel = options.cancel;
    const long evaluations_before = result.evaluations;
    if (options.progress)
      cmaes.progress = [&](const CmaesProgress& p) {
        options.progress({run, runs, evaluations_before + p.evaluations, p.best,
                          std::min(best_objective, p.best), seconds_since_start()});
      };
    const auto found =
        minimise_cmaes([&](std::span<const double> x) { return objective(to_maps(x)); },
                       to_vector(start_maps), cmaes);
    result.evaluations += found.evaluations;
    result.runs = run + 1;
    if (found.deadline_reached) result.time_capped = true;

    best_objective = std::min(best_objective, found.value);

    // Candidates: the searched maps and their ICP refinement. Keep the one whose attractor
    // matches L best: the collage objective guides the search, the attractor is what the user
    // gets.
    options.cancel.check("fit");
    std::vector<std::vector<AffineMap>> candidates{to_maps(found.x)};
    if (options.refine_iterations > 0)
      candidates.push_back(refine_icp(target, candidates.front(),
                                      {options.refine_iterations, options.objective.max_factor}));
    for (auto& maps : candidates) {
      options.cancel.check("fit");
      Ifs ifs;
      ifs.name = options.name;
      ifs.maps = std::move(maps);
      ifs.probabilities = default_probabilities(ifs.maps);
      if (!(ifs.contraction() < 1)) continue;  // past the objective's wall: never chosen
      CollageReport report = assess(target, ifs, {options.quality, options.seed, options.threads});
      if (report.iou > best_iou) {
        best_iou = report.iou;
        result.ifs = std::move(ifs);
        result.report = std::move(report);
        result.objective = objective(result.ifs.maps);
      }
    }
  }
  if (result.ifs.maps.empty())
    throw Error(ErrorKind::invalid_argument,
                "fit: no contractive IFS was found within the budget (raise --max-seconds)");
  result.seconds = seconds_since_start();
  return result;
}

}  // namespace ifsfx::collage
