// SPDX-License-Identifier: Apache-2.0
// Growing from fewer maps (issue 32 item 3). The re-seed (reseed.h) swaps one map for another
// where A misses; growing takes more apart: it drops the maps that pay least, lets the rest
// re-spread over L by a whole-set re-optimisation, then adds maps one at a time, each onto the
// region of L that A misses and whose map (the range/domain search, search.h) makes the best set,
// re-optimising the whole set after each addition, until N maps again. The fit runs it on a share
// of the attractor's stages (FitOptions::grow_share, fit_attractor.cpp).
#pragma once

#include <functional>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "collage/attractor_loss.h"
#include "collage/search.h"
#include "ifs/affine_map.h"

namespace ifsfx::collage {

struct GrowOptions {
  int drop = 2;           // the maps that pay least, dropped first (at most N − 1)
  int regions = 4;        // the largest missed regions screened for each added map
  double min_region = 0;  // the smallest region worth a map, as a share of L's pixels
  SearchOptions search;   // the range/domain search for one region
  // The whole set re-optimised: after the drop (step 0) and after each added map (steps 1 ..
  // steps − 1; steps = 1 + the maps dropped). None: the sets are kept as they are.
  std::function<std::vector<AffineMap>(std::vector<AffineMap>, int step, int steps)> reoptimise;
  // Told of the work done outside `reoptimise`, as it is done: renderings of the judge's raster
  // and range/domain searches (the fit counts them as evaluations).
  std::function<void(int renderings, int searches)> charge;
};

// `maps` with one map more: the map of `target` (L, the working raster) onto one of the
// options.regions largest regions of L that A misses on `judge`'s raster (error_maps, reseed.h;
// at least options.min_region of L), whichever makes the set with the best IoU on `judge`;
// `spare` when A misses no region of that size, so the set always grows by one.
std::vector<AffineMap> with_map_where_missed(const AttractorLoss& judge, const cv::Mat& target,
                                             std::span<const AffineMap> maps,
                                             const AffineMap& spare,
                                             const GrowOptions& options = {});

// `from` less its options.drop maps that pay least on `judge` (least_paying, reseed.h), then grown
// back by with_map_where_missed — the dropped maps, least paying first, are the spares — with
// options.reoptimise after the drop and after each addition. Always as many maps as `from`; `from`
// itself for a single map. Deterministic: the search and the judge do not depend on the thread
// count.
std::vector<AffineMap> grow_maps(const AttractorLoss& judge, const cv::Mat& target,
                                 std::span<const AffineMap> from, const GrowOptions& options = {});

}  // namespace ifsfx::collage
