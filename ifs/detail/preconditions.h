// SPDX-License-Identifier: Apache-2.0
// The checks the public entry points of one family share, written once (OpenImageIO's IBAprep):
// every function of the family calls its helper first, so each refuses the same bad input with
// the same message, naming the library's own parameter ("quality", "threads"), never a
// command-line flag (the command line translates: cli/cli_errors.h).
#pragma once

#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/view.h"

namespace ifsfx::detail {

// What a chaos-game entry point (chaos_game_samples, visit_counts, render_attractor,
// render_measure, top_symbols, compute_steal_map) was given. Fields a function does not take
// stay unset.
struct ChaosGameInputs {
  const Ifs& ifs;
  std::string name;  // how messages call the IFS ("colouring IFS"); default: its name, or "ifs"
  // Also require that the IFS contracts on average (tops and steal maps follow its addresses);
  // otherwise only what the walk needs: maps, finite coefficients, one probability per map (the
  // map picker's table has a column per map), ≥ 0 and not all 0, colours.
  bool contracting = false;
  int threads = 0;
  int burn_in = 0;
  std::optional<double> quality;  // points per pixel
  std::optional<cv::Size> size;   // of the raster
  std::optional<Box> view;        // the plane rectangle shown
  double margin = 0;              // auto-framing margin
  // An options type's sampling: its threads, quality, view and margin are checked as well.
  const Sampling* sampling = nullptr;
};

// Throws Error{invalid_ifs} for the IFS (see validate()) and Error{invalid_argument} for the
// rest: "threads: must be 0 (all cores) to 256 (got -1)", "burn_in: ...", "quality: must be a
// positive number of points per pixel, at most 1e+06 (got 0)", "size: ...", "view: ...", "margin:
// ...".
void check_chaos_game(const ChaosGameInputs& in);

}  // namespace ifsfx::detail
