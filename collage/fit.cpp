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
#include "collage/cut_partition.h"
#include "collage/distance.h"
#include "collage/fit_attractor.h"
#include "collage/fitting.h"
#include "collage/initialise.h"
#include "collage/optimise.h"
#include "collage/refine.h"
#include "collage/search.h"
#include "collage/similarity_cover.h"
#include "collage/similarity_scan.h"
#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/render.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::collage {

using detail::Budget;
using detail::Clock;
using detail::Fitting;

namespace {

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

// L and A on the target's grid, grown (by whole pixels, so the grids coincide) to hold the
// attractor's bounding box: a part of A outside the square still counts in h and IoU.
struct Canvas {
  cv::Mat l, a;     // CV_8UC1 0/255
  cv::Rect square;  // where the target's raster lies in them
};

Canvas render_on_canvas(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options,
                        bool& clipped) {
  const int size = target.cols;
  const Box bounds = attractor_bounds(ifs, options.seed);
  const int left = margin_pixels(-bounds.x0, size, clipped);
  const int right = margin_pixels(bounds.x1 - 1, size, clipped);
  const int bottom = margin_pixels(-bounds.y0, size, clipped);
  const int top = margin_pixels(bounds.y1 - 1, size, clipped);
  const cv::Size canvas_size(size + left + right, size + top + bottom);
  const Box view{-static_cast<double>(left) / size, -static_cast<double>(bottom) / size,
                 1 + static_cast<double>(right) / size, 1 + static_cast<double>(top) / size};
  Canvas c;
  c.a = render_attractor(ifs, canvas_size,
                         {.sampling = {.view = view,
                                       .quality = options.quality,
                                       .seed = options.seed,
                                       .threads = options.threads}});
  c.square = cv::Rect(left, top, size, size);
  c.l = cv::Mat(canvas_size, CV_8UC1, cv::Scalar(0));
  target.copyTo(c.l(c.square));
  return c;
}

}  // namespace

double attractor_iou(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "attractor_iou: the target must be a non-empty square CV_8UC1 raster");
  validate(ifs, "attractor_iou");
  bool clipped = false;
  const Canvas canvas = render_on_canvas(target, ifs, options, clipped);
  return iou(canvas.l, canvas.a);
}

const char* to_string(FitPhase phase) noexcept {
  switch (phase) {
    case FitPhase::partition:
      return "partition";
    case FitPhase::search:
      return "search";
    case FitPhase::refine:
      return "refine";
    case FitPhase::attractor:
      return "attractor";
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

  const Canvas canvas = render_on_canvas(target, ifs, options, r.clipped);
  r.attractor = canvas.a(canvas.square).clone();
  if (cv::countNonZero(canvas.a) == 0) {
    r.hausdorff = std::numeric_limits<double>::infinity();
    r.iou = 0;
  } else {
    r.hausdorff = hausdorff(canvas.l, canvas.a) / size;
    r.iou = iou(canvas.l, canvas.a);
  }
  r.parts = part_coverage(target, r.attractor);
  return r;
}

namespace {

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

// The shares of the budget (time and evaluations alike) at which the stages of the search
// initialisation end: the pool, the runs that choose and descend, CMA-ES on the collage.
struct Shares {
  double pool, descend, cmaes;
  double polish = 1;  // where the polish on W^k(L) ends
};
Shares shares(FitMethod method) {
  // The attractor's stages need most of the budget: the collage only gives them starts.
  return method == FitMethod::collage ? Shares{0.25, 0.45, 0.5} : Shares{0.1, 0.18, 0.2, 0.4};
}

// Searches the partitions of `target` (the first always, the next ones while less than the
// pool's share of the time is spent) and pools the maps kept for every piece, with the
// moment-matched start maps; their footprints are taken on `objective`'s raster.
Pool search_pool(Fitting& fitting, const cv::Mat& target, const CollageObjective& objective) {
  const FitOptions& options = fitting.options;
  SearchOptions search = options.search;
  search.threads = options.threads;
  search.cancel = options.cancel;
  const double share = shares(options.method).pool;
  search.deadline = fitting.budget.at(share);
  Pool pool;
  pool.maps = initial_maps(target, options.maps);
  for (int p = 0; p < options.partitions; ++p) {
    if (p > 0 && Clock::now() >= fitting.budget.at(share)) break;
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

// FitMethod::attractor's extra start: N maps chosen from the maps searched for L cut a quarter
// from either end of its principal axis (cut_partition.h) — one large copy of L and small ones
// at the end, as self-similar shapes such as a fern are made — descended on the collage.
// Nothing when L cannot be cut so (N = 1, or an end too small).
std::optional<std::vector<AffineMap>> cut_start(Fitting& fitting, const cv::Mat& target,
                                                DescentOptions descent) {
  const FitOptions& options = fitting.options;
  if (options.maps < 2) return std::nullopt;
  SearchOptions search = options.search;
  search.threads = options.threads;
  search.cancel = options.cancel;
  search.deadline = fitting.budget.at(0.65);
  Pool pool;
  for (const bool from_low : {true, false}) {
    try {
      const cv::Mat labels = cut_partition(target, options.maps, 0.25, from_low);
      for (const auto& piece : search_pieces(target, labels, options.maps, search))
        for (const auto& c : piece) pool.maps.push_back(c.map);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::invalid_argument) throw;
    }
  }
  if (std::ssize(pool.maps) < options.maps) return std::nullopt;
  for (const auto& f : pool.maps) pool.footprints.push_back(fitting.objective.footprint(f));
  fitting.budget.evaluations += std::ssize(pool.maps) / options.maps;
  std::vector<AffineMap> start;
  for (std::size_t i : select_maps(fitting.objective, pool.footprints, options.maps,
                                   {.deadline = search.deadline, .cancel = options.cancel}))
    start.push_back(pool.maps[i]);
  // A move costs one map's image: N of them make one evaluation; 5% of the budget.
  descent.max_evaluations = std::max(12L, fitting.budget.evaluations_at(0.05) * options.maps);
  descent.deadline = fitting.budget.at(0.65);
  const DescentResult descended = descend_each_map(fitting.objective, start, descent);
  fitting.budget.evaluations += descended.evaluations / options.maps;
  return descended.maps;
}

// FitMethod::attractor's starts from the self-similarity scan: covers of L by N copies of itself
// (similarity_scan.h, similarity_cover.h), searched on the finest picture of L there is — on the
// working raster a fern's fronds are one solid leaf, in which any smaller leaf fits. The scan's
// cost is counted, whatever the clock; its linear parts stop at 45% of the time. Nothing below
// 10 times its cost in evaluations.
std::vector<std::vector<AffineMap>> similarity_starts(Fitting& fitting) {
  const FitOptions& options = fitting.options;
  const cv::Mat& source = options.fine_target.empty() ? fitting.target : options.fine_target;
  SimilarityScanOptions scan;
  // A fixed cost: more than a tenth of a small budget would leave the refinement too little.
  if (options.similarity_starts < 1 || source.cols < scan.size ||
      10 * scan_cost(scan) > options.max_evaluations)
    return {};
  scan.threads = options.threads;
  scan.cancel = options.cancel;
  scan.deadline = fitting.budget.at(0.45);
  fitting.report(FitPhase::search, fitting.chooser.result.runs, fitting.best_objective);
  const std::vector<SelfCopy> copies = scan_self_similarity(source, scan);
  fitting.budget.evaluations += scan_cost(scan);
  std::vector<std::vector<AffineMap>> covers =
      greedy_covers(source, copies, {.maps = options.maps, .covers = options.similarity_starts});
  for (auto& cover : covers) {
    cover = refine_icp(source, std::move(cover),
                       {options.refine_iterations, options.objective.max_factor,
                        fitting.budget.at(0.45), options.cancel});
    fitting.chooser.consider(cover);
  }
  return covers;
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
  // The descended maps of every run, best first, with their collage objective; no two alike.
  std::vector<std::pair<double, std::vector<AffineMap>>> distinct;
};

// Whether two sets of maps differ (some coefficient by more than 0.01, in order).
bool differ(const std::vector<AffineMap>& a, const std::vector<AffineMap>& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto x = a[i].coefficients(), y = b[i].coefficients();
    for (std::size_t k = 0; k < x.size(); ++k)
      if (std::abs(x[k] - y[k]) > 0.01) return true;
  }
  return false;
}

// Adds the descended maps of a run to `runs.distinct` unless a run found them already.
void keep_distinct(Runs& runs, double value, const std::vector<AffineMap>& maps) {
  for (const auto& [v, m] : runs.distinct)
    if (!differ(m, maps)) return;
  runs.distinct.emplace_back(value, maps);
  std::stable_sort(runs.distinct.begin(), runs.distinct.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

// Runs until the descent's share of the budget (45% for FitMethod::collage): the greedy choice
// first, then the next-best ones (up to options.restarts), then kicks of the best maps so far, each
// descended map by map.
Runs choose_and_descend(Fitting& fitting, const Pool& pool, DescentOptions& descent) {
  const FitOptions& options = fitting.options;
  Budget& budget = fitting.budget;
  std::vector<std::vector<std::size_t>> tried;
  Runs runs;
  double best_value = std::numeric_limits<double>::infinity();
  const double share = shares(options.method).descend;
  int run = 0;
  for (;; ++run) {
    // The first run always happens, so that a fit has an answer however small its budget.
    if (run > 0 &&
        (budget.evaluations >= budget.evaluations_at(share) || Clock::now() >= descent.deadline))
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
        std::max(12L, (budget.evaluations_at(share) - budget.evaluations) * options.maps);
    const DescentResult descended = descend_each_map(fitting.objective, start, descent);
    budget.evaluations += descended.evaluations / options.maps;
    fitting.best_objective = std::min(fitting.best_objective, descended.value);
    // Render only what may beat the best attractor: objective and IoU go together closely.
    if (descended.value < 1.05 * best_value) fitting.chooser.consider(descended.maps);
    keep_distinct(runs, descended.value, descended.maps);
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
  polish.deadline = budget.at(shares(options.method).polish, 2 * fitting.chooser.reserve());
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
  descent.deadline = budget.at(shares(options.method).descend);
  const Runs runs = choose_and_descend(fitting, pool, descent);
  if (runs.best.empty()) return;  // not even one run: the budget is spent
  // All maps at once: CMA-ES on the collage objective, then ICP (each kept only if its
  // attractor is better).
  const Shares share = shares(options.method);
  if (!budget.expired())
    fitting.refine(runs.run, runs.best, 0.005,
                   std::max(2L, budget.evaluations_at(share.cmaes) - budget.evaluations),
                   budget.at(share.cmaes));
  budget.cap_at(share.polish);
  polish_attractor(fitting, pool, descent, runs.run);
  budget.uncap();
  if (options.method != FitMethod::attractor || fitting.chooser.result.ifs.maps.empty()) return;
  // The attractor's own stages, from the best attractor so far, the self-similar covers, the cut
  // start and the best distinct runs.
  std::vector<std::vector<AffineMap>> starts = {fitting.chooser.result.ifs.maps};
  for (auto& cover : similarity_starts(fitting)) starts.push_back(std::move(cover));
  if (auto cut = cut_start(fitting, coarse_raster(fitting.target), descent))
    starts.push_back(std::move(*cut));
  for (const auto& [value, maps] : runs.distinct)
    if (std::ssize(starts) < std::max(1, options.starts)) starts.push_back(maps);
  optimise_attractor(fitting, std::move(starts), fitting.chooser.result.runs);
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
  if (!options.fine_target.empty() && (options.fine_target.type() != CV_8UC1 ||
                                       options.fine_target.rows != options.fine_target.cols))
    throw Error(ErrorKind::invalid_argument, "fine_target: must be a square CV_8UC1 raster");
  Fitting fitting(target, options);
  bool interrupted = false;
  try {
    if (options.init == Initialisation::moments)
      fit_from_moments(fitting);
    else
      fit_from_search(fitting);
  } catch (const Error& e) {
    // A stop request keeps the best so far, when there is one.
    if (e.kind() != ErrorKind::interrupted || fitting.chooser.result.ifs.maps.empty()) throw;
    interrupted = true;
  }

  FitResult result = std::move(fitting.chooser.result);
  // Every candidate was judged on the fine raster too, when there is one: its best is the answer.
  if (fitting.chooser.judges_fine()) {
    result.ifs = std::move(fitting.chooser.fine_best.ifs);
    result.report = std::move(fitting.chooser.fine_best.report);
    result.objective = fitting.objective(result.ifs.maps);
  }
  if (result.ifs.maps.empty())
    throw Error(ErrorKind::invalid_argument,
                "fit: no contractive IFS was found within the budget (raise max_seconds)");
  result.interrupted = interrupted;
  result.evaluations = fitting.budget.evaluations;
  result.time_capped = fitting.budget.capped;
  result.seconds = fitting.budget.seconds();
  return result;
}

}  // namespace ifsfx::collage
