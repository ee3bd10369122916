// SPDX-License-Identifier: Apache-2.0
// The arguments of `ifsfx fit` and the steps it takes, shared with `ifsfx studio`'s fit job so
// that a shape fitted in the page gives the maps the command gives for the same settings.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "collage/fit.h"
#include "ifs/cancel.h"

namespace ifsfx::app {

struct FitArgs {
  std::string target;
  std::string output;
  int maps = 4;
  std::uint64_t seed = 1;
  collage::Initialisation init = collage::Initialisation::search;
  collage::FitMethod method = collage::FitMethod::attractor;
  std::optional<double> threshold;
  bool invert = false;
  bool json = false;
  bool progress = false;
  double max_seconds = 30;
  long max_evaluations = 250000;
  // FitOptions::reseed_share and ::grow_share: the attractor stages' shares given to re-seeding
  // and to growing maps where the error is (issue 32 item 3); 0 switches either off.
  double reseed_share = collage::FitOptions{}.reseed_share;
  double grow_share = collage::FitOptions{}.grow_share;
  std::string preview;
  std::string size = "128";
  int threads = 0;
};

// The working raster's side from "S" or "SxS"; throws Error{parse} or Error{invalid_argument}
// naming --size.
int working_size(const std::string& text);

// The number of maps checked (1..32); throws Error{invalid_argument} naming `what` (the
// command's -n, Python's n).
void check_fit_maps(int maps, const std::string& what = "-n");

// The budgets' ranges: seconds in [0, kMaxFitSeconds] (0: no cap), evaluations in
// 2..kMaxFitEvaluations.
inline constexpr double kMaxFitSeconds = 1e6;
inline constexpr long kMaxFitEvaluations = 100000000;
// How a door names the budgets (Python: max_seconds, max_evaluations).
struct FitBudgetNames {
  std::string seconds = "--max-seconds", evaluations = "--max-evaluations";
};
// Throws Error{invalid_argument} "NAME: must be in [0, 1000000] (got X)" for a budget out of its
// range.
void check_fit_budgets(double max_seconds, long max_evaluations, const FitBudgetNames& names = {});

// The largest share of the attractor's stages re-seeding or growing may take.
inline constexpr double kMaxFitShare = 0.15;
// How a door names the shares (Python: reseed_share, grow_share).
struct FitShareNames {
  std::string reseed = "--reseed-share", grow = "--grow-share";
};
// Throws Error{invalid_argument} "NAME: must be in [0, 0.15] (got X)" for a share out of its
// range.
void check_fit_shares(double reseed_share, double grow_share, const FitShareNames& names = {});

// The target's shape (args.target: its alpha, else its dark pixels; args.threshold, args.invert)
// on the working raster of args.size. Throws what load_target and working_raster throw.
cv::Mat fit_raster(const FitArgs& args);

// The target's shape on a raster 4 times finer than the working one, in the same frame: where
// the report's fine IoU is measured (a fit that only looks good at the working raster says so).
cv::Mat fit_fine_raster(const FitArgs& args);

// The fit's options from the arguments (maps, seed, init, method, budgets, shares, threads, the
// target's stem as the IFS's name), polling `cancel`. The caller adds options.fine_target
// (fit_fine_raster) to have the report's fine IoU.
collage::FitOptions fit_options(const FitArgs& args, const CancelToken& cancel);

// The description a fitted preset carries: "fitted by ifsfx fit to TARGET: IoU 0.912 (512²:
// 0.874), s 0.563", the part in brackets when a fine raster was given.
std::string fit_summary(const FitArgs& args, const collage::FitResult& result);

}  // namespace ifsfx::app
