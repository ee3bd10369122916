// SPDX-License-Identifier: Apache-2.0
// Maps where the error is (issue 32 item 3). An optimiser that moves all maps at once slides the
// pieces it has towards what A misses; it does not put a new piece there. The re-seed does: it
// finds the regions of L that A leaves empty (and those where A spills out of L), takes out the
// map that pays least for itself — the one whose removal costs the least IoU — and puts in its
// place the map of L onto the largest missed region that the range/domain search (search.h)
// finds, the region being the one piece. The fit then re-optimises the whole set briefly and keeps
// it only if its IoU on the fine raster rises (fit_attractor.cpp).
#pragma once

#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "collage/attractor_loss.h"
#include "collage/search.h"
#include "ifs/affine_map.h"

namespace ifsfx::collage {

// An 8-connected region of an error map.
struct ErrorRegion {
  int area = 0;  // pixels
  cv::Mat mask;  // CV_8UC1 0/255 of the rasters' size
};

// Where A and L differ, on one raster: the missed pixels L \ A and the spilled ones A \ L, each
// opened by a 3×3 square first (a sliver a pixel wide along an edge is the pieces' misalignment,
// which ICP and CMA-ES mend, not a part of L left out), and their connected regions of at least
// `min_area` pixels, largest first (ties: the first in row order).
struct ErrorMaps {
  cv::Mat missed, spilled;  // CV_8UC1 0/255, after the opening
  std::vector<ErrorRegion> missed_regions, spilled_regions;
};

// `target` and `attractor` are R×R CV_8UC1 rasters of the unit square (AttractorLoss::target()
// and ::raster() give them). Throws Error{invalid_argument} for rasters that differ in size or
// type.
ErrorMaps error_maps(const cv::Mat& target, const cv::Mat& attractor, int min_area = 1);

// The indices of `maps`, the map that pays least for itself first: by the IoU of A against L on
// `loss`'s raster that each one's removal leaves, highest first (ties: by index). N renderings of
// A. Empty for a single map.
std::vector<int> least_paying(const AttractorLoss& loss, std::span<const AffineMap> maps);

// The maps of L (the working raster `target`) onto `region` (a 0/255 mask of any square size on
// the same frame, resampled to the target's size and cut to L) that the range/domain search
// keeps, best first (at most options.keep, distinct); none when the region keeps fewer than
// `min_pixels` pixels of L at the target's size.
std::vector<AffineMap> maps_onto_region(const cv::Mat& target, const cv::Mat& region,
                                        const SearchOptions& options = {}, int min_pixels = 4);

}  // namespace ifsfx::collage
