// SPDX-License-Identifier: Apache-2.0
// Rendering a fractal flame as flam3-render does (Draves & Reckase, "The Fractal Flame
// Algorithm"; docs/flames.md "Rendering"): the chaos game over the xforms (§3, §5), plotted
// into a supersampled histogram of colour and density (§4), density estimation (§7), the
// spatial filter, and the log-density display with gamma, vibrancy and highlight power (§4, §6).
//
// The one call a door needs, flame in, pixels out:
//   const Flame f = read_flame("pack.flame:spiral");
//   cv::Mat bgr = render_flame(f, {.seed = 7, .threads = 0});
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include <opencv2/core.hpp>

#include "flame/flame.h"
#include "ifs/cancel.h"

namespace ifsfx::flame {

struct FlameRenderOptions {
  // Picture size; none: the flame's own. The framing is kept: the scale follows the width, as
  // flam3-render's size scale does (scale × width / flame's width).
  std::optional<cv::Size> size;
  // Samples per output pixel (before the zoom's 4^zoom); none: the flame's own.
  std::optional<double> quality;
  std::uint64_t seed = 1;
  int threads = 0;     // 0 = all cores; the bytes do not depend on it
  CancelToken cancel;  // polled per chunk of points and per band of rows: Error{interrupted}
  // Called with the fraction done, in [0, 1], from the calling thread or a worker (at most one
  // call at a time); it must be cheap.
  std::function<void(double fraction)> progress;
  int channels = 3;   // 3: BGR over the flame's background; 4: BGRA, the flame over the
                      // background's alpha (opaque unless the file makes it transparent)
  int depth = CV_8U;  // CV_8U, CV_16U or CV_32F (float in [0, 1])
  int burn_in = 15;   // iterations each walker discards before plotting (flam3's fuse)
  // The variations evaluated in float lanes (eight a register on AVX2, float-accuracy
  // polynomials; the walk, the sums and the camera stay in double) where a float batch form
  // exists; false: double lanes (four a register), the renderer's arithmetic before 27 Nov.
  bool float_lanes = true;
};

struct FlameRenderStats {
  std::uint64_t points = 0;    // chaos-game iterations plotted or tried (burn-in excluded)
  std::uint64_t reseeded = 0;  // points that left the finite numbers and were re-seeded
  double seconds = 0;          // wall time of the whole render
  double coverage = 0;         // fraction of output pixels with any density
};

// The picture of `flame`. Throws Error{invalid_argument} for options or camera values out of
// range, Error{interrupted} when cancelled.
cv::Mat render_flame(const Flame& flame, const FlameRenderOptions& options = {},
                     FlameRenderStats* stats = nullptr);

}  // namespace ifsfx::flame
