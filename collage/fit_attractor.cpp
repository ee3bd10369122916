// SPDX-License-Identifier: Apache-2.0
#include "collage/fit_attractor.h"

#include <algorithm>

#include "collage/attractor_fit.h"
#include "collage/attractor_loss.h"
#include "collage/grow.h"
#include "collage/reseed.h"
#include "ifs/rng.h"

namespace ifsfx::collage::detail {

namespace {

// Where each stage ends, as a share of what the collage stages left (evaluations and time alike).
// The re-seed (FitOptions::reseed_share) runs first in the fine raster's share, and what it leaves
// goes to the fine raster's first round: a re-seed that finds nothing to do changes nothing.
// Growing (FitOptions::grow_share) takes the end of the escapes' share.
constexpr double kCoarseEnd = 0.2, kMiddleEnd = 0.35, kEscapeEnd = 0.5, kFineStart = 0.7;
// The fine raster's stage (FitOptions::fine_target, finish_on_fine): chaos-game points per pixel
// of its square, CMA-ES's first step, and the rounds of CMA-ES and ICP. Measured on the fern's
// picture, N = 4, 100000 evaluations: one round without ICP gains 0.883 -> 0.888 (a first step
// of 0.01: nothing); with ICP after it 0.898; two rounds 0.908, three 0.909.
constexpr double kFinePoints = 1, kFineSigma = 0.003;
constexpr int kFineRounds = 2;
// How many escapes share their stage, and how far each moves the maps (coordinates of
// map_params.h: radians, logits, 0.1 plane units).
constexpr int kEscapes = 4;
constexpr double kEscapeScale = 0.05;
// The re-seed (reseed.h): its tries, each an equal part of its share; the chaos-game points per
// pixel of the raster that finds the error regions (4: few holes in A's raster where A is
// solid); the smallest region worth a map, as a share of L's pixels there; CMA-ES's first step
// for the re-optimisation; what a range/domain search for one piece costs (~50 ms: 200
// evaluations' time).
constexpr int kReseeds = 4;
constexpr double kJudgePoints = 4, kMinRegion = 0.002, kReseedSigma = 0.01;
constexpr long kSearchCost = 200;
// What one try screens: the largest regions, and the maps that pay least; a set is re-optimised
// when its IoU on the working raster is at most this far below the candidate's.
constexpr int kScreenRegions = 4, kScreenMaps = 2;
constexpr double kReseedSlack = 0.005;
// Growing (FitOptions::grow_share): how many of the maps that pay least are dropped before the
// maps are grown back (at most N - 1), and CMA-ES's first step for each re-optimisation on 64².
constexpr int kGrowDrop = 2;
constexpr double kGrowSigma = 0.03;
// The working raster's stage (kEscapeEnd to the fine raster's or the re-seed's start): CMA-ES's
// first step, and the part of the stage that screens its starts when there are several
// (screened_start). Measured on the fern's picture, 250000 evaluations: a part of 0.3 ends at
// 0.894–0.906 at 512² (seeds 1–4), 0.5 at 0.901–0.927 and 0.7 at 0.903–0.918 (seeds 1–8).
constexpr double kLastSigma = 0.01, kScreenShare = 0.7;

// Evaluations are counted as collage evaluations of about the same time: one of the attractor
// loss costs a unit per 20000 of its chaos-game points and canvas pixels (the chaos game's AVX2
// kernel ~7 ns a point; the hit raster's scan and the coverage's distance transform ~5 ns a
// canvas pixel): 0.3 units on 32², 1.3 on 64², 4.6 on 128² at 4 points per pixel, 43 on 512² at
// one. (Until the eighth pass, with the scalar double chaos game of ~30 ns a point, a unit per
// 5000 points: 3.3 on 64², 13 on 128², 52 on 512².)
double unit_cost(const AttractorLoss& loss) {
  const double points = loss.points() * loss.size() * loss.size();
  const double canvas = static_cast<double>(loss.canvas_side()) * loss.canvas_side();
  return (points + canvas) / 20000;
}

// The attractor's stages of one fit and what they share.
class Stages {
 public:
  Stages(Fitting& fitting, int run)
      : fitting_(fitting),
        options_(fitting.options),
        budget_(fitting.budget),
        start_time_(Clock::now()),
        end_time_(budget_.at(1.0, 2 * fitting.chooser.reserve())),
        start_evaluations_(budget_.evaluations),
        total_evaluations_(std::max(0L, budget_.evaluations_left())),
        run_(run),
        centre_(fitting.objective.centroid()),
        reseed_(std::clamp(options_.reseed_share, 0.0, (1 - kFineStart) / kFineRounds)),
        grow_(std::clamp(options_.grow_share, 0.0, kEscapeEnd - kMiddleEnd)) {
    // The levels are cut from the finest picture of L there is, kept where L covers any part
    // of a pixel, as A's raster is (attractor_loss.h): a half-covered coarse target drops a
    // fern's fronds, and its loss is lower for a wrong fern than for the true one (0.21
    // against 0.30 on 32², 0.14 against 0.18 on 64²).
    const cv::Mat& source = options_.fine_target.empty() ? fitting.target : options_.fine_target;
    const int size = fitting.target.cols;
    for (int level : {std::min(32, size), std::min(64, size), size})
      levels_.emplace_back(
          source, AttractorLossOptions{
                      .size = level, .seed = stream_seed(options_.seed, level), .keep = 0});
    if (fitting.chooser.judges_fine()) {
      const int fine = options_.fine_target.cols;
      levels_.emplace_back(options_.fine_target,
                           AttractorLossOptions{.size = fine,
                                                .points = kFinePoints,
                                                .seed = stream_seed(options_.seed, fine),
                                                .keep = 0});
    }
  }

  // CMA-ES at `level` from `start` with the evaluations left before `fraction` of the stages'
  // share, divided among `ways` runs, and until that share of the time.
  AttractorRefined refine(int level, const std::vector<AffineMap>& start, double sigma,
                          double fraction, int ways) {
    const AttractorLoss& loss = levels_[static_cast<std::size_t>(level)];
    const double cost = unit_cost(loss);
    const long units = evaluations_until(fraction) / std::max(1, ways);
    AttractorRefineOptions o;
    o.centre = centre_;
    o.max_factor = options_.objective.max_factor;
    o.sigma = sigma;
    o.max_evaluations = std::max(2L, static_cast<long>(static_cast<double>(units) / cost));
    o.seed = stream_seed(options_.seed ^ 0x61747472616374ULL, static_cast<std::uint64_t>(run_));
    o.threads = options_.threads;
    o.deadline = time_at(fraction, ways);
    o.cancel = options_.cancel;
    const long before = budget_.evaluations;
    if (options_.progress)
      o.progress = [&, before, cost](const CmaesProgress& p) {
        options_.progress({FitPhase::attractor, run_, fitting_.runs,
                           before + static_cast<long>(static_cast<double>(p.evaluations) * cost),
                           p.best, p.best, std::max(fitting_.chooser.best_iou, 0.0),
                           budget_.seconds()});
      };
    AttractorRefined found = refine_on_attractor(loss, start, o);
    budget_.evaluations += static_cast<long>(static_cast<double>(found.evaluations) * cost);
    if (found.deadline_reached) budget_.capped = true;
    ++run_;
    return found;
  }

  // Whether the stage that ends at `fraction` has time and evaluations left.
  bool open(double fraction) const {
    return evaluations_until(fraction) >= 2 && Clock::now() < time_at(fraction, 1);
  }

  // Of `a` and `b`, the one with the lower loss on the working raster (two evaluations).
  const std::vector<AffineMap>& better_at_last_level(const std::vector<AffineMap>& a,
                                                     const std::vector<AffineMap>& b) {
    const AttractorLoss& last = levels_[2];
    budget_.evaluations += static_cast<long>(2 * unit_cost(last));
    return last(b) < last(a) ? b : a;
  }

  // Evaluations of `loss` (or their equivalent) spent outside a refine().
  void charge(const AttractorLoss& loss, int evaluations) {
    budget_.evaluations += static_cast<long>(evaluations * unit_cost(loss));
  }
  void charge(long evaluations) { budget_.evaluations += evaluations; }

  // The re-seed's share: it starts where the fine raster's stage does (at most that stage's first
  // round), or, without a fine raster, takes the end of the working raster's.
  double reseed_share() const { return reseed_; }
  double reseed_begin() const { return has_fine() ? kFineStart : 1.0 - reseed_; }

  // Growing's share ends where the escapes' did; the escapes keep what is before it.
  double grow_share() const { return grow_; }
  double escape_end() const { return kEscapeEnd - grow_; }

  bool has_fine() const { return levels_.size() > 3; }
  const AttractorLoss& level(int k) const { return levels_[static_cast<std::size_t>(k)]; }
  Fitting& fitting() { return fitting_; }
  Point centre() const { return centre_; }
  int run() const { return run_; }

 private:
  long evaluations_until(double fraction) const {
    return start_evaluations_ +
           static_cast<long>(fraction * static_cast<double>(total_evaluations_)) -
           budget_.evaluations;
  }
  // The time at `fraction` of the stages' share, or, for one of `ways` runs, its part of what
  // is left until then.
  Clock::time_point time_at(double fraction, int ways) const {
    if (options_.max_seconds <= 0) return Clock::time_point::max();
    const auto end = start_time_ + std::chrono::duration_cast<Clock::duration>(
                                       fraction * (end_time_ - start_time_));
    const auto now = Clock::now();
    if (end <= now) return end;
    return now + (end - now) / std::max(1, ways);
  }

  Fitting& fitting_;
  const FitOptions& options_;
  Budget& budget_;
  Clock::time_point start_time_, end_time_;
  long start_evaluations_, total_evaluations_;
  int run_;
  Point centre_;
  double reseed_;
  double grow_;
  std::vector<AttractorLoss> levels_;
};

// Perturb-and-accept from `current` (its loss at the middle level `value`) until the escapes'
// share is spent: all maps moved at random, re-optimised, accepted by the Metropolis rule at a
// temperature that falls to 0. Returns the best maps met, and their loss in `value`.
std::vector<AffineMap> escape(Stages& stages, std::vector<AffineMap> current, double& value) {
  const FitOptions& options = stages.fitting().options;
  std::vector<AffineMap> best = current;
  double best_value = value, current_value = value;
  Rng rng(stream_seed(options.seed ^ 0x65736361706500ULL, 0));
  for (int k = 0; k < kEscapes; ++k) {
    const double end = kMiddleEnd + (stages.escape_end() - kMiddleEnd) * (k + 1) / kEscapes;
    if (!stages.open(end)) break;
    const auto start =
        perturbed(current, stages.centre(), options.objective.max_factor, kEscapeScale, rng);
    const AttractorRefined found = stages.refine(1, start, 0.03, end, 1);
    // The temperature: a loss worse by 1% of the current one is taken with odds 1/e at first.
    const double temperature = 0.01 * current_value * (1 - static_cast<double>(k) / kEscapes);
    if (metropolis_accepts(found.value - current_value, temperature, rng.uniform())) {
      current = found.maps;
      current_value = found.value;
    }
    if (found.value < best_value) {
      best = found.maps;
      best_value = found.value;
    }
  }
  value = best_value;
  return best;
}

// The last word is the fine raster's (the last 30% of the stages' share), in rounds: CMA-ES on
// the loss cut at its own size, where a pixel is 0.002 of the square (a fern's true maps moved by
// 0.003 lose 0.15 of IoU there), from the best candidate on it, by small steps (0.003: a sixth of
// its pixel, 0.17°); then ICP on it (refine.h), which pulls each map onto its piece once the
// maps are that close. The chooser keeps each only if its fine IoU rises. One point per pixel of
// the square (6 per pixel of a fern) keeps an evaluation at 4 times the working raster's.
void finish_on_fine(Stages& stages) {
  Fitting& fitting = stages.fitting();
  const FitOptions& options = fitting.options;
  const RefineOptions icp{options.refine_iterations, options.objective.max_factor,
                          fitting.budget.at(1.0, fitting.chooser.reserve()), options.cancel};
  for (int k = 0; k < kFineRounds; ++k) {
    const double end = kFineStart + (1 - kFineStart) * (k + 1) / kFineRounds;
    if (!stages.open(end)) break;
    const std::vector<AffineMap> moved =
        stages.refine(3, fitting.chooser.fine_best.ifs.maps, kFineSigma, end, 1).maps;
    fitting.chooser.consider(moved);
    if (options.refine_iterations > 0)
      fitting.chooser.consider(refine_icp(options.fine_target, moved, icp));
  }
}

// The maps of the best candidate on the fine raster (the working raster's best without one).
const std::vector<AffineMap>& best_maps(Stages& stages) {
  const Chooser& chooser = stages.fitting().chooser;
  return stages.has_fine() ? chooser.fine_best.ifs.maps : chooser.result.ifs.maps;
}
double best_iou(Stages& stages) {
  const Chooser& chooser = stages.fitting().chooser;
  return stages.has_fine() ? chooser.fine_best.report.fine_iou : chooser.best_iou;
}

// The working raster's stage's start when the fit has a fine raster: each distinct one of
// `candidates` refined on the working raster with an equal part of kScreenShare of the stage
// (which ends at `end`), and then the chooser's best on the fine raster, of them and of all
// before. Which start ends best is told by no raster's ranking before this CMA-ES has run from
// it: on the fern's picture (250000 evaluations, seed 3) the 32² and 64² stages leave a fern of
// 0.795 at 512², the best there, whose last stages end at 0.847; refined here, the collage
// stages' best of 0.787 passes it, and the fit ends at 0.908 (bench/README.md, eleventh pass).
std::vector<AffineMap> screened_start(Stages& stages,
                                      std::vector<std::vector<AffineMap>> candidates, double end) {
  std::vector<std::vector<AffineMap>> distinct;
  for (auto& maps : candidates)
    if (!maps.empty() && std::find(distinct.begin(), distinct.end(), maps) == distinct.end())
      distinct.push_back(std::move(maps));
  const double screen_end = kEscapeEnd + (end - kEscapeEnd) * kScreenShare;
  if (distinct.size() > 1)
    for (std::size_t k = 0; k < distinct.size(); ++k) {
      if (!stages.open(screen_end)) break;
      const int ways = static_cast<int>(distinct.size() - k);
      stages.fitting().chooser.consider(
          stages.refine(2, distinct[k], kLastSigma, screen_end, ways).maps);
    }
  // The chooser has judged a contractive set before these stages, so this is never empty; were
  // it, the first candidate would do.
  const std::vector<AffineMap>& chosen = best_maps(stages);
  return chosen.empty() && !distinct.empty() ? distinct.front() : chosen;
}

// The search's options for one region's maps: the fit's, held below its contraction wall.
SearchOptions region_search(const FitOptions& options) {
  SearchOptions search = options.search;
  search.max_factor = std::min(search.max_factor, options.objective.max_factor);
  search.threads = options.threads;
  search.cancel = options.cancel;
  return search;
}

// One re-seed's start: the set, the region its new map covers and its IoU on the working raster.
struct Reseeded {
  std::vector<AffineMap> maps;
  const ErrorRegion* region = nullptr;
  double iou = -1;
};

// The best re-seeded set, by IoU on the working raster: each of the kScreenRegions largest
// missed regions not tried in vain, each map the range/domain search finds onto it, in place of
// each of the kScreenMaps maps of `current` that pay least. One rendering per set on the
// working raster (a 128² rendering: a sixteenth of the judge's), so many are cheap to screen.
Reseeded screen(Stages& stages, const std::vector<AffineMap>& current, const ErrorMaps& errors,
                const cv::Mat& tried, const SearchOptions& search) {
  const AttractorLoss& working = stages.level(2);
  const std::vector<int> order = least_paying(working, current);
  stages.charge(working, static_cast<int>(current.size()));
  Reseeded best;
  int regions = 0;
  for (const ErrorRegion& region : errors.missed_regions) {
    if (regions == kScreenRegions) break;
    if (2 * cv::countNonZero(region.mask & tried) >= region.area) continue;
    ++regions;
    const std::vector<AffineMap> placed =
        maps_onto_region(stages.fitting().target, region.mask, search);
    stages.charge(kSearchCost);
    for (std::size_t w = 0; w < std::min<std::size_t>(kScreenMaps, order.size()); ++w)
      for (const AffineMap& f : placed) {
        std::vector<AffineMap> maps = current;
        maps[static_cast<std::size_t>(order[w])] = f;
        stages.charge(working, 1);
        if (const double iou = working.terms(maps).iou; iou > best.iou)
          best = {std::move(maps), &region, iou};
      }
  }
  return best;
}

// Maps where the error is (issue 32 item 3, reseed.h), on [begin, end) of the stages' share in
// up to kReseeds tries. Each try finds, on the finest raster, the regions of L that the best
// candidate's A misses, screens the re-seeded sets (above), and when the best of them is within
// kReseedSlack of the candidate's IoU on the working raster, re-optimises it by CMA-ES on the
// working raster's loss from a small step and aligns it by ICP on the finest raster; the
// chooser keeps it only if its IoU there rises. A region whose try did not gain is not tried
// again. When no set comes near, the re-seed ends and its evaluations go to the next stage.
void reseed(Stages& stages, double begin, double end) {
  Fitting& fitting = stages.fitting();
  const FitOptions& options = fitting.options;
  const cv::Mat& finest = stages.has_fine() ? options.fine_target : fitting.target;
  const AttractorLoss judge(finest, {.size = finest.cols,
                                     .points = kJudgePoints,
                                     .seed = stream_seed(options.seed ^ 0x7265736565644ULL, 0),
                                     .keep = 0});
  const int min_area = std::max(4, static_cast<int>(kMinRegion * cv::countNonZero(judge.target())));
  const SearchOptions search = region_search(options);
  const RefineOptions icp{options.refine_iterations, options.objective.max_factor,
                          fitting.budget.at(1.0, fitting.chooser.reserve()), options.cancel};
  cv::Mat tried(judge.target().size(), CV_8UC1, cv::Scalar(0));  // regions tried in vain
  for (int k = 0; k < kReseeds; ++k) {
    const double stage_end = begin + (end - begin) * (k + 1) / kReseeds;
    if (!stages.open(stage_end)) break;
    const std::vector<AffineMap> current = best_maps(stages);
    if (current.empty()) break;
    const ErrorMaps errors = error_maps(judge.target(), judge.raster(current), min_area);
    stages.charge(judge, 1);
    const Reseeded found = screen(stages, current, errors, tried, search);
    const double now = stages.level(2).terms(current).iou;
    stages.charge(stages.level(2), 1);
    if (found.region == nullptr || found.iou < now - kReseedSlack) break;
    const double before = best_iou(stages);
    const auto moved = stages.refine(2, found.maps, kReseedSigma, stage_end, 1).maps;
    fitting.chooser.consider(found.maps);
    fitting.chooser.consider(moved);
    if (options.refine_iterations > 0) fitting.chooser.consider(refine_icp(finest, moved, icp));
    if (!(best_iou(stages) > before)) tried |= found.region->mask;
  }
}

// Growing from fewer maps (issue 32 item 3, grow.h) on [begin, end) of the stages' share, from
// `from`: the regions A misses are found on the working raster (4 points per pixel), each
// re-optimisation is CMA-ES on 64² with an equal part of the share. A step with no evaluations or
// time left still adds its map (only its re-optimisation is skipped): the result has N maps.
std::vector<AffineMap> grow(Stages& stages, const std::vector<AffineMap>& from, double begin,
                            double end) {
  Fitting& fitting = stages.fitting();
  const AttractorLoss& working = stages.level(2);
  GrowOptions o;
  o.drop = kGrowDrop;
  o.regions = kScreenRegions;
  o.min_region = kMinRegion;
  o.search = region_search(fitting.options);
  o.reoptimise = [&](std::vector<AffineMap> maps, int step, int steps) {
    const double step_end = begin + (end - begin) * (step + 1) / steps;
    if (!stages.open(step_end)) return maps;
    fitting.report(FitPhase::attractor, stages.run(), fitting.best_objective);
    return stages.refine(1, maps, kGrowSigma, step_end, 1).maps;
  };
  o.charge = [&](int renderings, int searches) {
    fitting.options.cancel.check("fit");
    stages.charge(working, renderings);
    stages.charge(static_cast<long>(searches) * kSearchCost);
  };
  return grow_maps(working, fitting.target, from, o);
}

}  // namespace

void optimise_attractor(Fitting& fitting, std::vector<std::vector<AffineMap>> starts, int run) {
  if (starts.empty()) return;
  Stages stages(fitting, run);
  // starts.front() is kept for the last stage (see below).
  const int count = static_cast<int>(starts.size());
  // Coarse: every start on 32², as far as its share goes.
  std::vector<AttractorRefined> coarse;
  for (int k = 0; k < count; ++k) {
    if (k > 0 && !stages.open(kCoarseEnd * (k + 1) / count)) break;
    fitting.report(FitPhase::attractor, stages.run(), fitting.best_objective);
    coarse.push_back(stages.refine(0, starts[static_cast<std::size_t>(k)], 0.05,
                                   kCoarseEnd * (k + 1) / count, 1));
  }
  std::stable_sort(coarse.begin(), coarse.end(),
                   [](const auto& a, const auto& b) { return a.value < b.value; });
  // Middle: the best two on 64².
  std::vector<AttractorRefined> middle;
  for (std::size_t k = 0; k < std::min<std::size_t>(2, coarse.size()); ++k) {
    if (k > 0 && !stages.open(kMiddleEnd)) break;
    middle.push_back(stages.refine(1, coarse[k].maps, 0.03, kMiddleEnd, static_cast<int>(2 - k)));
  }
  std::stable_sort(middle.begin(), middle.end(),
                   [](const auto& a, const auto& b) { return a.value < b.value; });
  fitting.chooser.consider(middle.front().maps);
  // Escapes on 64², then the best on the working raster.
  double value = middle.front().value;
  const std::vector<AffineMap> best = escape(stages, middle.front().maps, value);
  if (best != middle.front().maps) fitting.chooser.consider(best);
  // Growing from fewer maps, from the escapes' best: the grown set competes for the last stage.
  std::vector<AffineMap> grown;
  if (stages.grow_share() > 0) {
    grown = grow(stages, best, stages.escape_end(), stages.escape_end() + stages.grow_share());
    if (grown != best)
      fitting.chooser.consider(grown);
    else
      grown.clear();
  }
  // The coarse levels' optimum need not be the working raster's nor the fine raster's. With a
  // fine raster the last stage screens the best there, the best on the working raster, the
  // escapes' best and the grown set; without one it starts from the best on the working raster's
  // loss of the escapes' best, the best attractor before these stages and the grown set.
  const double last_end = stages.has_fine() ? kFineStart : stages.reseed_begin();
  std::vector<AffineMap> final_maps;
  if (stages.has_fine()) {
    final_maps = screened_start(
        stages, {best_maps(stages), fitting.chooser.result.ifs.maps, best, grown}, last_end);
  } else {
    final_maps = stages.better_at_last_level(best, starts.front());
    if (!grown.empty()) final_maps = stages.better_at_last_level(final_maps, grown);
  }
  if (stages.open(last_end)) {
    final_maps = stages.refine(2, final_maps, kLastSigma, last_end, 1).maps;
    fitting.chooser.consider(final_maps);
  }
  // ICP on the collage (refine.h) aligns the maps below a pixel where L is self-similar, as a
  // fractal's own picture is (W(L) = L exactly); the chooser keeps it only if A is better.
  if (fitting.options.refine_iterations > 0) {
    const RefineOptions icp{fitting.options.refine_iterations, fitting.options.objective.max_factor,
                            fitting.budget.at(1.0, fitting.chooser.reserve()),
                            fitting.options.cancel};
    fitting.chooser.consider(refine_icp(fitting.target, final_maps, icp));
    if (!fitting.options.fine_target.empty())
      fitting.chooser.consider(refine_icp(fitting.options.fine_target, final_maps, icp));
  }
  if (stages.reseed_share() > 0)
    reseed(stages, stages.reseed_begin(), stages.reseed_begin() + stages.reseed_share());
  if (stages.has_fine()) finish_on_fine(stages);
  fitting.chooser.result.runs = stages.run();
}

}  // namespace ifsfx::collage::detail
