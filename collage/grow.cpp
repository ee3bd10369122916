// SPDX-License-Identifier: Apache-2.0
#include "collage/grow.h"

#include <algorithm>

#include "collage/reseed.h"

namespace ifsfx::collage {

namespace {

void charge(const GrowOptions& options, int renderings, int searches) {
  if (options.charge) options.charge(renderings, searches);
}

}  // namespace

std::vector<AffineMap> with_map_where_missed(const AttractorLoss& judge, const cv::Mat& target,
                                             std::span<const AffineMap> maps,
                                             const AffineMap& spare, const GrowOptions& options) {
  const int min_area =
      std::max(4, static_cast<int>(options.min_region * cv::countNonZero(judge.target())));
  const ErrorMaps errors = error_maps(judge.target(), judge.raster(maps), min_area);
  charge(options, 1, 0);
  std::vector<AffineMap> best(maps.begin(), maps.end());
  best.push_back(spare);
  double best_iou = -1;
  const std::size_t regions = std::min(errors.missed_regions.size(),
                                       static_cast<std::size_t>(std::max(0, options.regions)));
  for (std::size_t r = 0; r < regions; ++r) {
    const std::vector<AffineMap> placed =
        maps_onto_region(target, errors.missed_regions[r].mask, options.search);
    charge(options, 0, 1);
    for (const AffineMap& f : placed) {
      std::vector<AffineMap> grown(maps.begin(), maps.end());
      grown.push_back(f);
      const double iou = judge.terms(grown).iou;
      charge(options, 1, 0);
      if (iou > best_iou) {
        best = std::move(grown);
        best_iou = iou;
      }
    }
  }
  return best;
}

std::vector<AffineMap> grow_maps(const AttractorLoss& judge, const cv::Mat& target,
                                 std::span<const AffineMap> from, const GrowOptions& options) {
  const int n = static_cast<int>(from.size());
  const int drop = std::min(n - 1, options.drop);
  if (drop < 1) return {from.begin(), from.end()};
  const std::vector<int> order = least_paying(judge, from);
  charge(options, n, 0);
  // The kept maps in their order; the dropped ones least paying first (the spares).
  std::vector<AffineMap> maps, spares;
  for (int k = 0; k < n; ++k)
    if (std::find(order.begin(), order.begin() + drop, k) == order.begin() + drop)
      maps.push_back(from[static_cast<std::size_t>(k)]);
  for (int k = 0; k < drop; ++k) spares.push_back(from[static_cast<std::size_t>(order[k])]);
  for (int step = 0; step <= drop; ++step) {
    if (step > 0)
      maps = with_map_where_missed(judge, target, maps, spares[static_cast<std::size_t>(step - 1)],
                                   options);
    if (options.reoptimise) maps = options.reoptimise(std::move(maps), step, drop + 1);
  }
  return maps;
}

}  // namespace ifsfx::collage
