// SPDX-License-Identifier: Apache-2.0
// Sub-pixel refinement of a collage by symmetric iterative closest points (ICP). The collage
// objective is piecewise constant below a pixel, so the evolution strategy leaves each map a
// fraction of a pixel off — and a thin attractor drifts off its 1-pixel-wide target by exactly
// that. Least squares over thousands of point pairs finds each map to a small fraction of a pixel.
#pragma once

#include <chrono>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/cancel.h"

namespace ifsfx::collage {

struct RefineOptions {
  int iterations = 30;       // ICP rounds (each: pair the points, then solve per map)
  double max_factor = 0.97;  // a map whose solution reaches this contraction keeps its old value
  // No round starts at or after this time (the rounds done are kept). The default never comes.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Polled before every round; a stop request throws Error{interrupted}.
  CancelToken cancel;
};

// Refines `maps` against `target` (a working raster, target.h). Each round pairs points both
// ways — every image point f_n(p) with the centre of L nearest to it, and every centre t of L with
// the image point f_n(p) nearest to it — and replaces f_n by the affine least-squares fit of its
// pairs p → t. Deterministic. Returns the maps of the last round.
std::vector<AffineMap> refine_icp(const cv::Mat& target, std::vector<AffineMap> maps,
                                  const RefineOptions& options = {});

}  // namespace ifsfx::collage
