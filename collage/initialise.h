// SPDX-License-Identifier: Apache-2.0
// A deterministic starting IFS for the collage fit: split L into N parts and map L onto each
// part by the affine map that matches the part's first and second moments (paper §2: the
// collage W(L) = ∪ f_n(L) should tile L, so each f_n(L) should look like one piece of it).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"

namespace ifsfx::collage {

enum class Split {
  principal_axes,    // split the part of largest inertia across its principal axis at its median,
                     // until there are N parts (no randomness: the first try of every fit)
  kmeans_plus_plus,  // N seeds drawn by k-means++ from `seed` (the restarts)
};

struct InitOptions {
  Split split = Split::principal_axes;
  std::uint64_t seed = 1;    // k-means++ only
  int lloyd_iterations = 8;  // k-means refinement of the parts after the split
  // Multi-part shapes: give each connected component (8-connected) of L its own parts — one
  // each, the rest in proportion to their areas (D'Hondt) — and split each component on its own,
  // so that no part straddles a gap. A component below |L| / (4 N) pixels, or beyond the N
  // largest, is too small to carry a part of its own: its pixels join the nearest part (that
  // part's map has to cover it). Off: L is split as one set of pixels.
  bool by_component = false;
};

// Labels 0..N−1 of L's pixels (CV_32SC1 of the target's size, −1 outside L): the split, then
// Lloyd's k-means iterations on pixel coordinates (within each component when by_component).
cv::Mat partition(const cv::Mat& target, int n, const InitOptions& options = {});

// N maps of the IFS plane (working raster convention, target.h), one per part: f_n(x) =
// A (x − μ_L) + μ_n with A = Σ_n^{1/2} R Σ_L^{−1/2}, so that f_n(L) has the part's centroid μ_n
// and covariance Σ_n; the orthogonal R (8 rotations by 45°, each with or without a reflection)
// is the one whose f_n(L) overlaps the part best. A map with factor ≥ 0.95 is shrunk to 0.9.
std::vector<AffineMap> initial_maps(const cv::Mat& target, int n, const InitOptions& options = {});

}  // namespace ifsfx::collage
