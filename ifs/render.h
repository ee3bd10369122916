// SPDX-License-Identifier: Apache-2.0
// Rendering an IFS to an image by the chaos game: the attractor as a set, and its invariant
// measure (paper Fig. 1 left and centre; docs/design.md §4).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/chaos_game.h"
#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/view.h"

namespace ifsfx {

struct RenderOptions {
  Sampling sampling;      // view, margin, quality (points per pixel), seed, threads, cancel
  int supersample = 1;    // render at K× the size and box-filter down (measure mode)
  double gamma = 2.2;     // measure mode: display gamma of the log-density tone map
  double brightness = 4;  // measure mode: k of v = log(1 + k·count/mean) / log(1 + k·max/mean)
};

struct RenderStats {
  std::uint64_t points = 0;  // points plotted (burn-in excluded)
  double seconds = 0;        // wall time of the chaos game
  double coverage = 0;       // fraction of output pixels hit
  Box view;                  // the plane rectangle actually shown
};

// The attractor as a set: CV_8UC1, 255 where at least one point landed, 0 elsewhere.
//   auto mask = render_attractor(fern, {1024, 1024});
cv::Mat render_attractor(const Ifs& ifs, cv::Size size, const RenderOptions& options = {},
                         RenderStats* stats = nullptr);

// The invariant measure: per-pixel visit counts tone-mapped by v = log(1 + k·c) / log(1 + k·max)
// then gamma, coloured by map (palette coordinate c_k = (c_{k-1} + c_σk) / 2 through the IFS's
// colours or the default palette), on black. CV_32FC3 BGR in [0, 1].
cv::Mat render_measure(const Ifs& ifs, cv::Size size, const RenderOptions& options = {},
                       RenderStats* stats = nullptr);

// Raw visit counts on `viewport` (CV_32SC1), the kernel behind both modes, exposed for tests and
// benchmarks. `points` is the number of points plotted in total.
cv::Mat visit_counts(const Ifs& ifs, const Viewport& viewport, std::uint64_t points,
                     const ChaosGameOptions& options = {});

// The default palette: colour of map n of N (an evenly spaced, perceptually ordered ramp).
Rgb palette_colour(std::size_t n, std::size_t count);
// That ramp at palette coordinate t ∈ [0, 1] (map n of N sits at n / (N − 1)).
Rgb palette_ramp(double t);

}  // namespace ifsfx
