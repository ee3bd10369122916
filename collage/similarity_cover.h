// SPDX-License-Identifier: Apache-2.0
// Starts for the fit from the copies of L inside itself (similarity_scan.h, issue 32): N copies
// chosen by greedy set cover of L — each step takes the copy that covers most of what is left,
// less what it spills — so that the union W(L) = ∪ w_n(L) is L, as it is exactly for a fractal's
// own picture (paper eq. 1). A few distinct covers, each from another first copy, give the
// attractor's refinement (attractor_fit.h) several starts.
#pragma once

#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "collage/similarity_scan.h"
#include "ifs/affine_map.h"

namespace ifsfx::collage {

struct CoverOptions {
  int maps = 4;      // N, the copies of each cover (≥ 1)
  int covers = 3;    // cover k starts from the k-th best first copy; alike covers are dropped
  int size = 256;    // the raster the covers are counted on (resampled_mask; at most the target's)
  double spill = 1;  // the cost of a pixel of w(L) outside L, against one of L newly covered
  // ... and of one of L covered before: overlapping copies fill a solid shape, but the pieces
  // of a fractal's own picture hardly overlap.
  double overlap = 0.25;
};

// Up to options.covers distinct sets of N maps from `copies` (as scan_self_similarity returns
// them for `target`), best first; none when there are fewer than N copies. A step's gain is
// |w(L) ∩ L \ covered| − spill · |w(L) \ L₁| − overlap · |w(L) ∩ covered|, L₁ L grown
// by a pixel, on resampled_mask(target,
// size); ties go to the earlier copy.
//   auto starts = greedy_covers(raster, scan_self_similarity(raster), {.maps = 4});
std::vector<std::vector<AffineMap>> greedy_covers(const cv::Mat& target,
                                                  std::span<const SelfCopy> copies,
                                                  const CoverOptions& options = {});

}  // namespace ifsfx::collage
