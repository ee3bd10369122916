// SPDX-License-Identifier: Apache-2.0
// What the stages of one fit share (fit.cpp, fit_attractor.cpp): the clock and the evaluation
// count, the chooser that renders candidates and keeps the best attractor, the progress reports.
// Internal to collage/: not part of the library's interface.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "collage/collage.h"
#include "collage/fit.h"
#include "collage/optimise.h"
#include "collage/refine.h"
#include "ifs/ifs.h"
#include "ifs/rng.h"

namespace ifsfx::collage::detail {

using Clock = std::chrono::steady_clock;

// The clock and the evaluation count of one fit.
class Budget {
 public:
  explicit Budget(const FitOptions& o)
      : start_(Clock::now()),
        deadline_(o.max_seconds > 0 ? start_ + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(o.max_seconds))
                                    : Clock::time_point::max()),
        seconds_(o.max_seconds),
        max_evaluations_(o.max_evaluations),
        cap_(o.max_evaluations) {}

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
  long evaluations_left() const { return std::min(cap_, max_evaluations_) - evaluations; }
  // Until uncap(), evaluations_left() counts only to `fraction` of max_evaluations: a stage
  // that runs "while evaluations are left" keeps to its share.
  void cap_at(double fraction) { cap_ = evaluations_at(fraction); }
  void uncap() { cap_ = max_evaluations_; }
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
  long cap_;
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
    if (judges_fine()) {
      report.fine_iou = attractor_iou(options_.fine_target, ifs, fine_assess());
      report.fine_size = options_.fine_target.cols;
    }
    assess_seconds_ = std::max(assess_seconds_, budget_.seconds() - before);
    if (judges_fine() &&
        (fine_best.ifs.maps.empty() || report.fine_iou > fine_best.report.fine_iou))
      fine_best = {ifs, report};
    if (report.iou > best_iou) {
      best_iou = report.iou;
      result.ifs = std::move(ifs);
      result.report = std::move(report);
      result.objective = objective_(result.ifs.maps);
    }
  }

  // Whether every candidate is judged on the finer raster of the target's frame too
  // (FitOptions::fine_target). A working raster blurs the thin parts a fit may get right or
  // wrong, so its ranking is not the fine one's (a fern's candidates: 0.869 on 128² is 0.729 on
  // 512², 0.819 is 0.883); the fine IoU chooses the answer, the working raster's best stays
  // the start of the later stages. One rendering of 4S² at a quarter of the quality per
  // candidate (4 times a working raster's): time, not evaluations, so `max_seconds = 0` fits
  // are the same with it.
  bool judges_fine() const { return fine_has_pixels_; }
  AssessOptions fine_assess() const {
    return {options_.quality / 4, options_.seed, options_.threads};
  }

  // The best candidate by IoU on the fine raster; the first is kept on a tie. Empty unless
  // judges_fine().
  struct Judged {
    Ifs ifs;
    CollageReport report;
  };
  Judged fine_best;

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
  bool fine_has_pixels_ =
      !options_.fine_target.empty() && cv::countNonZero(options_.fine_target) > 0;
};

inline std::vector<double> to_vector(const std::vector<AffineMap>& maps) {
  std::vector<double> x;
  for (const auto& f : maps)
    for (double k : f.coefficients()) x.push_back(k);
  return x;
}

inline std::vector<AffineMap> to_maps(std::span<const double> x) {
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

}  // namespace ifsfx::collage::detail
