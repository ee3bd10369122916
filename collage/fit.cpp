// SPDX-License-Identifier: Apache-2.0
#include "collage/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/combine.h"
#include "collage/distance.h"
#include "collage/initialise.h"
#include "collage/optimise.h"
#include "collage/refine.h"
#include "collage/search.h"
#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/render.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::collage {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxMaps = 32;

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

// Each component of L and how much of it A covers, largest first.
std::vector<PartCoverage> part_coverage(const cv::Mat& target, const cv::Mat& attractor) {
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(target, labels, stats, centroids, 8, CV_32S);
  std::vector<long> hit(static_cast<std::size_t>(count), 0);
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (attractor.at<std::uint8_t>(r, c)) ++hit[static_cast<std::size_t>(labels.at<int>(r, c))];
  const double size = target.cols;
  std::vector<PartCoverage> parts;
  for (int k = 1; k < count; ++k) {
    const int area = stats.at<int>(k, cv::CC_STAT_AREA);
    parts.push_back(
        {area,
         {(centroids.at<double>(k, 0) + 0.5) / size, 1 - (centroids.at<double>(k, 1) + 0.5) / size},
         static_cast<double>(hit[static_cast<std::size_t>(k)]) / area});
  }
  std::stable_sort(parts.begin(), parts.end(),
                   [](const PartCoverage& a, const PartCoverage& b) { return a.area > b.area; });
  return parts;
}

}  // namespace

const char* to_string(FitPhase phase) noexcept {
  switch (phase) {
    case FitPhase::partition:
      return "partition";
    case FitPhase::search:
      return "search";
    case FitPhase::refine:
      return "refine";
  }
  return "?";
}

CollageReport assess(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "assess: the target must be a non-empty square CV_8UC1 working raster");
  validate(ifs, "assess");
  const int size = target.cols;
  CollageReport r;
  r.pixel = 1.0 / size;
  r.raster_error = std::sqrt(0.5) * r.pixel;
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
  const Box view{-static_cast<double>(left) / size, -static_cast<double>(bottom) / size,
                 1 + static_cast<double>(right) / size, 1 + static_cast<double>(top) / size};
  const cv::Mat canvas_a = render_attractor(ifs, canvas_size,
                                            {.sampling = {.view = view,
                                                          .quality = options.quality,
                                                          .seed = options.seed,
                                                          .threads = options.threads}});
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
  r.parts = part_coverage(target, r.attractor);
  return r;
}

namespace {

// The clock and the evaluation count of one fit.
class Budget {
 public:
  explicit Budget(const FitOptions& o)
      : start_(Clock::now()),
        deadline_(o.max_seconds > 0 ? start_ + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(o.max_seconds))
                                    : Clock::time_point::max()),
        seconds_(o.max_seconds),
        max_evaluations_(o.max_evaluations) {}

  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  Clock::time_point deadline() const { return deadline_; }
  bool expired() const { return Clock::now() >= deadline_; }
  // Whether a unit of work expected to take `seconds` ends before the deadline.
  bool room_for(double seconds) const {
    return deadline_ == Clock::time_point::max() ||
           Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(seconds)) <
               deadline_;
  }
  long evaluations_left() const { return max_evaluations_ - evaluations; }
  // The time when `fraction` of max_seconds has passed, less `reserve` seconds (never, without
  // a cap), and the evaluation count at `fraction` of max_evaluations.
  Clock::time_point at(double fraction, double reserve = 0) const {
    if (deadline_ == Clock::time_point::max()) return deadline_;
    return start_ + std::chrono::duration_cast<Clock::duration>(
                        std::chrono::duration<double>(fraction * seconds_ - reserve));
  }
  long evaluations_at(double fraction) const {
    return static_cast<long>(fraction * static_cast<double>(max_evaluations_));
  }

  long evaluations = 0;
  bool capped = false;

 private:
  Clock::time_point start_, deadline_;
  double seconds_;
  long max_evaluations_;
};

// The candidates of a fit, judged by their rendered attractor: keeps the best by IoU(L, A).
class Chooser {
 public:
  Chooser(const cv::Mat& target, const CollageObjective& objective, const FitOptions& options,
          Budget& budget)
      : target_(target), objective_(objective), options_(options), budget_(budget) {}

  // Renders the attractor of `maps` and keeps them if it beats the best so far. Skipped when
  // the rendering would not end before the deadline (the first candidate is always rendered,
  // so that a fit always has an answer).
  void consider(std::vector<AffineMap> maps) {
    options_.cancel.check("fit");
    Ifs ifs;
    ifs.name = options_.name;
    ifs.maps = std::move(maps);
    ifs.probabilities = default_probabilities(ifs.maps);
    if (!(ifs.contraction() < 1)) return;  // past the objective's wall: never chosen
    if (!result.ifs.maps.empty() && !budget_.room_for(reserve())) {
      budget_.capped = true;
      return;
    }
    const double before = budget_.seconds();
    CollageReport report =
        assess(target_, ifs, {options_.quality, options_.seed, options_.threads});
    assess_seconds_ = std::max(assess_seconds_, budget_.seconds() - before);
    if (report.iou > best_iou) {
      best_iou = report.iou;
      result.ifs = std::move(ifs);
      result.report = std::move(report);
      result.objective = objective_(result.ifs.maps);
    }
  }

  // Seconds to keep free before the deadline for the renderings that judge a last candidate.
  double reserve() const { return 1.5 * assess_seconds_; }

  FitResult result;
  double best_iou = -1;

 private:
  const cv::Mat& target_;
  const CollageObjective& objective_;
  const FitOptions& options_;
  Budget& budget_;
  double assess_seconds_ = 0;
};

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

// What every run shares: the objective, the budget, the chooser and the progress reports.
struct Fitting {
  const cv::Mat& target;
  const FitOptions& options;
  const CollageObjective objective;
  Budget budget;
  Chooser chooser;
  double best_objective = std::numeric_limits<double>::infinity();
  int runs = 0;

  Fitting(const cv::Mat& t, const FitOptions& o)
      : target(t),
        options(o),
        objective(t, o.objective),
        budget(o),
        chooser(t, objective, o, budget),
        runs(o.restarts + 1) {}

  void report(FitPhase phase, int run, double objective_value) const {
    if (!options.progress) return;
    options.progress({phase, run, runs, budget.evaluations, objective_value,
                      std::min(best_objective, objective_value), std::max(chooser.best_iou, 0.0),
                      budget.seconds()});
  }

  // One run from `start`: CMA-ES on the collage objective with `evaluations` and until
  // `deadline`, then ICP; both results are rendered and judged.
  void refine(int run, const std::vector<AffineMap>& start, double sigma, long evaluations,
              Clock::time_point deadline) {
    CmaesOptions cmaes;
    cmaes.sigma = sigma;
    cmaes.max_evaluations = evaluations;
    // Room is left for rendering the two candidates of the run.
    cmaes.deadline = std::min(deadline, budget.at(1.0, 2 * chooser.reserve()));
    cmaes.seed = stream_seed(options.seed ^ 0x636f6c6c616765ULL, static_cast<std::uint64_t>(run));
    cmaes.threads = options.threads;
    cmaes.cancel = options.cancel;
    const long evaluations_before = budget.evaluations;
    if (options.progress)
      cmaes.progress = [&](const CmaesProgress& p) {
        options.progress({FitPhase::refine, run, runs, evaluations_before + p.evaluations, p.best,
                          std::min(best_objective, p.best), std::max(chooser.best_iou, 0.0),
                          budget.seconds()});
      };
    const auto found = minimise_cmaes(
        [&](std::span<const double> x) { return objective(to_maps(x)); }, to_vector(start), cmaes);
    budget.evaluations += found.evaluations;
    if (found.deadline_reached) budget.capped = true;
    best_objective = std::min(best_objective, found.value);

    // Candidates: the searched maps and their ICP refinement. The collage objective guides the
    // search; the attractor is what the user gets.
    const auto searched = to_maps(found.x);
    chooser.consider(searched);
    if (options.refine_iterations > 0)
      chooser.consider(refine_icp(target, searched,
                                  {options.refine_iterations, options.objective.max_factor,
                                   budget.at(1.0, chooser.reserve()), options.cancel}));
    report(FitPhase::refine, run, found.value);
  }

  // A time limit for a run given its share of what is left.
  Clock::time_point share_of_time(int run) const {
    if (options.max_seconds <= 0) return Clock::time_point::max();
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                              (options.max_seconds - budget.seconds()) / (runs - run)));
  }
};

// Issue 14's fit: every run starts from a moment-matched split (principal axes, then k-means++).
void fit_from_moments(Fitting& fitting) {
  const FitOptions& options = fitting.options;
  for (int run = 0; run < fitting.runs; ++run) {
    const long evaluations_left = fitting.budget.evaluations_left();
    if (evaluations_left < 2) break;
    if (fitting.budget.expired()) {
      fitting.budget.capped = true;
      break;
    }
    fitting.report(FitPhase::partition, run, fitting.best_objective);
    InitOptions init;
    if (run > 0) {
      init.split = Split::kmeans_plus_plus;
      init.seed = stream_seed(options.seed, static_cast<std::uint64_t>(run));
    }
    const auto start = initial_maps(fitting.target, options.maps, init);
    fitting.refine(run, start, run == 0 ? 0.03 : 0.05, evaluations_left / (fitting.runs - run),
                   fitting.share_of_time(run));
    fitting.chooser.result.runs = run + 1;
  }
}

// The partition `index`: principal axes first, then k-means++ seeds; one part per component at
// least.
cv::Mat partition_of(const cv::Mat& target, const FitOptions& options, int index) {
  InitOptions init;
  init.by_component = true;
  if (index > 0) {
    init.split = Split::kmeans_plus_plus;
    init.seed = stream_seed(options.seed, static_cast<std::uint64_t>(index));
  }
  return partition(target, options.maps, init);
}

// L on a raster of half the side, a pixel kept where L covers a quarter of it (so that thin parts
// survive): the search runs there, four times cheaper per candidate (the maps it finds live on
// the plane, not on a raster). Rasters below 96 pixels are kept as they are.
cv::Mat coarse_raster(const cv::Mat& target) {
  if (target.cols < 96) return target;
  cv::Mat half, mask;
  cv::resize(target, half, {target.cols / 2, target.rows / 2}, 0, 0, cv::INTER_AREA);
  cv::threshold(half, mask, 63, 255, cv::THRESH_BINARY);
  return cv::countNonZero(mask) >= 4 ? mask : target;
}

// The maps every run chooses from, with their footprints.
struct Pool {
  std::vector<AffineMap> maps;
  std::vector<Footprint> footprints;
};

// Searches the partitions of `target` (the first always, the next ones while less than a
// quarter of the time is spent) and pools the maps kept for every piece, with the
// moment-matched start maps; their footprints are taken on `objective`'s raster.
Pool search_pool(Fitting& fitting, const cv::Mat& target, const CollageObjective& objective) {
  const FitOptions& options = fitting.options;
  SearchOptions search = options.search;
  search.threads = options.threads;
  search.cancel = options.cancel;
  search.deadline = fitting.budget.at(0.25);
  Pool pool;
  pool.maps = initial_maps(target, options.maps);
  for (int p = 0; p < options.partitions; ++p) {
    if (p > 0 && Clock::now() >= fitting.budget.at(0.25)) break;
    fitting.report(FitPhase::partition, 0, fitting.best_objective);
    const cv::Mat labels = partition_of(target, options, p);
    fitting.report(FitPhase::search, 0, fitting.best_objective);
    for (const auto& piece : search_pieces(target, labels, options.maps, search))
      for (const auto& c : piece) pool.maps.push_back(c.map);
  }
  pool.footprints.resize(pool.maps.size());
  parallel_for(pool.maps.size(), options.threads,
               [&](std::size_t i, int) { pool.footprints[i] = objective.footprint(pool.maps[i]); });
  fitting.budget.evaluations += std::ssize(pool.maps) / options.maps;
  return pool;
}

// A start for a later run: the best maps so far with one or two of them swapped for pool maps
// drawn from (seed, run) — an iterated local search's kick.
std::vector<AffineMap> kicked(const std::vector<AffineMap>& best, const Pool& pool,
                              std::uint64_t seed, int run) {
  Rng rng(stream_seed(seed ^ 0x6b69636bULL, static_cast<std::uint64_t>(run)));
  std::vector<AffineMap> maps = best;
  const int swaps = 1 + static_cast<int>(rng.below(2));
  for (int k = 0; k < swaps; ++k)
    maps[rng.below(static_cast<std::uint32_t>(maps.size()))] =
        pool.maps[rng.below(static_cast<std::uint32_t>(pool.maps.size()))];
  return maps;
}

// Iterations of W in the final polish: W^k(L) is within s^k · h(L, A) of the attractor, under a
// pixel for the factors and distances of a fit.
constexpr int kPolishIterations = 5;

// The start of run `run` of the greedy choice (run 0) and the next-best ones: each addition drawn
// among the best few. Nothing when that choice was tried before.
std::optional<std::vector<AffineMap>> chosen_start(Fitting& fitting, const Pool& pool, int run,
                                                   Clock::time_point deadline,
                                                   std::vector<std::vector<std::size_t>>& tried) {
  const FitOptions& options = fitting.options;
  fitting.report(FitPhase::search, run, fitting.best_objective);
  SelectOptions select;
  select.spread = run == 0 ? 0 : 2;
  select.seed = stream_seed(options.seed, static_cast<std::uint64_t>(run));
  select.deadline = deadline;
  select.cancel = options.cancel;
  auto chosen = select_maps(fitting.objective, pool.footprints, options.maps, select);
  std::sort(chosen.begin(), chosen.end());
  if (std::find(tried.begin(), tried.end(), chosen) != tried.end()) return std::nullopt;
  tried.push_back(chosen);
  std::vector<AffineMap> start;
  for (std::size_t i : chosen) start.push_back(pool.maps[i]);
  return start;
}

// The best maps of the runs that choose N maps from the pool and descend one map at a time, and
// the number of runs.
struct Runs {
  std::vector<AffineMap> best;
  int run = 0;
};

// Runs until 45% of the budget: the greedy choice first, then the next-best ones (up to
// options.restarts), then kicks of the best maps so far, each descended map by map.
Runs choose_and_descend(Fitting& fitting, const Pool& pool, DescentOptions& descent) {
  const FitOptions& options = fitting.options;
  Budget& budget = fitting.budget;
  std::vector<std::vector<std::size_t>> tried;
  Runs runs;
  double best_value = std::numeric_limits<double>::infinity();
  int run = 0;
  for (;; ++run) {
    // The first run always happens, so that a fit has an answer however small its budget.
    if (run > 0 &&
        (budget.evaluations >= budget.evaluations_at(0.45) || Clock::now() >= descent.deadline))
      break;
    std::vector<AffineMap> start;
    if (run <= options.restarts) {
      auto chosen = chosen_start(fitting, pool, run, descent.deadline, tried);
      if (!chosen) continue;
      start = std::move(*chosen);
    } else {
      start = kicked(runs.best, pool, options.seed, run);
    }
    fitting.report(FitPhase::refine, run, fitting.best_objective);
    // A move costs one map's image: N of them make one evaluation.
    descent.max_evaluations =
        std::max(12L, (budget.evaluations_at(0.45) - budget.evaluations) * options.maps);
    const DescentResult descended = descend_each_map(fitting.objective, start, descent);
    budget.evaluations += descended.evaluations / options.maps;
    fitting.best_objective = std::min(fitting.best_objective, descended.value);
    // Render only what may beat the best attractor: objective and IoU go together closely.
    if (descended.value < 1.05 * best_value) fitting.chooser.consider(descended.maps);
    if (descended.value < best_value) {
      best_value = descended.value;
      runs.best = descended.maps;
    }
    fitting.report(FitPhase::refine, run, descended.value);
  }
  runs.run = run;
  return runs;
}

// A move maps W^k(L) again: k evaluations. Sweep by sweep, so that the progress goes on; a sweep
// that moves no map ends it, as the next one would repeat it exactly.
DescentResult polish_sweeps(Fitting& fitting, std::vector<AffineMap> start, DescentOptions& polish,
                            int sweeps, int run) {
  Budget& budget = fitting.budget;
  DescentResult polished{std::move(start)};
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    polish.max_evaluations = std::max(12L, budget.evaluations_left() / kPolishIterations);
    DescentResult step = descend_each_map(fitting.objective, polished.maps, polish);
    budget.evaluations += step.evaluations * kPolishIterations;
    const bool moved = step.maps != polished.maps;
    polished = std::move(step);
    fitting.report(FitPhase::refine, run, fitting.best_objective);
    if (!moved || polished.deadline_reached || budget.evaluations_left() < 2) break;
  }
  return polished;
}

// The attractor itself: descend on 1 − IoU(L, W^k(L)) from the best attractor so far; while
// time is left, kick the polished maps (as the runs do), descend on the collage and polish
// again, going on from whichever polish was best. Runs are counted on from `run`.
void polish_attractor(Fitting& fitting, const Pool& pool, DescentOptions& descent, int run) {
  const FitOptions& options = fitting.options;
  Budget& budget = fitting.budget;
  DescentOptions polish = descent;
  polish.iterations = kPolishIterations;
  polish.linear_step = 0.01;
  polish.pixel_step = 0.5;
  polish.halvings = 3;
  polish.sweeps = 1;  // one at a time, in polish_sweeps
  polish.deadline = budget.at(1.0, 2 * fitting.chooser.reserve());
  descent.deadline = polish.deadline;
  std::vector<AffineMap> current = fitting.chooser.result.ifs.maps;
  double current_value = std::numeric_limits<double>::infinity();
  for (int kick = 0;; ++kick, ++run) {
    if (budget.evaluations_left() < 2 || Clock::now() >= polish.deadline) break;
    fitting.report(FitPhase::refine, run, fitting.best_objective);
    std::vector<AffineMap> start = current;
    if (kick > 0) {
      descent.max_evaluations = std::max(12L, budget.evaluations_left() * options.maps);
      const DescentResult moved =
          descend_each_map(fitting.objective, kicked(current, pool, options.seed, run), descent);
      budget.evaluations += moved.evaluations / options.maps;
      start = moved.maps;
    }
    // 8 sweeps for the first polish, 2 after a kick.
    const DescentResult polished =
        polish_sweeps(fitting, std::move(start), polish, kick == 0 ? 8 : 2, run);
    if (polished.value < current_value) {
      current_value = polished.value;
      current = polished.maps;
      fitting.chooser.consider(polished.maps);
    }
  }
  fitting.chooser.result.runs = run;
  if (Clock::now() >= polish.deadline) budget.capped = true;
}

// The search initialisation's stages and their shares of the budget (time and evaluations
// alike): the pool of searched maps (search_pool: at most a quarter of the time), runs that
// choose N maps from the pool and descend one map at a time (to 45%), CMA-ES and ICP on all maps
// at once (to 50%), and a descent on the attractor's picture W^k(L) (the rest).
void fit_from_search(Fitting& fitting) {
  const FitOptions& options = fitting.options;
  Budget& budget = fitting.budget;
  const Pool pool = search_pool(fitting, coarse_raster(fitting.target), fitting.objective);
  DescentOptions descent;
  descent.threads = options.threads;
  descent.cancel = options.cancel;
  descent.deadline = budget.at(0.45);
  const Runs runs = choose_and_descend(fitting, pool, descent);
  if (runs.best.empty()) return;  // not even one run: the budget is spent

  // All maps at once: CMA-ES on the collage objective, then ICP (each kept only if its
  // attractor is better).
  if (!budget.expired())
    fitting.refine(runs.run, runs.best, 0.005,
                   std::max(2L, budget.evaluations_at(0.5) - budget.evaluations), budget.at(0.5));
  polish_attractor(fitting, pool, descent, runs.run);
}

}  // namespace

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
                fmt::format("max_seconds: must be ≥ 0 (got {})", options.max_seconds));
  Fitting fitting(target, options);
  if (options.init == Initialisation::moments)
    fit_from_moments(fitting);
  else
    fit_from_search(fitting);

  FitResult result = std::move(fitting.chooser.result);
  if (result.ifs.maps.empty())
    throw Error(ErrorKind::invalid_argument,
                "fit: no contractive IFS was found within the budget (raise max_seconds)");
  result.evaluations = fitting.budget.evaluations;
  result.time_capped = fitting.budget.capped;
  result.seconds = fitting.budget.seconds();
  return result;
}

}  // namespace ifsfx::collage
