// SPDX-License-Identifier: Apache-2.0
// The picture of a fit (`ifsfx fit --preview`): the target L, the collage W(L) = ∪ f_n(L) and the
// attractor A side by side, each of the N pieces in its own colour, so that one can see which map
// makes which part of the shape and where the collage misses or spills (paper §2, eq. 3).
#pragma once

#include <cstdint>

#include <opencv2/core.hpp>

#include "ifs/ifs.h"

namespace ifsfx::collage {

struct PreviewOptions {
  int scale = 2;         // each working-raster pixel drawn as scale × scale pixels (1..16)
  double quality = 256;  // chaos-game points per pixel for A's pieces (fractal tops)
  std::uint64_t seed = 1;
  int threads = 0;  // 0 = all cores
};

// The colour (BGR, 0..255) of piece n: hues a golden angle apart, so that any two pieces,
// neighbours included, are told apart.
cv::Vec3b piece_colour(int n);

// Three panels of S·scale pixels side by side (CV_8UC3, BGR) on the working raster of `target`:
//   1. L in white;
//   2. W(L): f_n(L) in piece_colour(n) (a higher n is painted over a lower one);
//   3. A: each pixel in the colour of the first symbol of its top address (docs/design.md §2), i.e.
//      of the piece f_n(A) on top there.
// In 2 and 3 the pixels of L left uncovered are dark grey, and those coloured outside L (spill)
// are dimmed to a third.
// The panels are separated by a thin gap.
//   write_image("preview.png", fit_preview(raster, result.ifs));
cv::Mat fit_preview(const cv::Mat& target, const Ifs& ifs, const PreviewOptions& options = {});

}  // namespace ifsfx::collage
