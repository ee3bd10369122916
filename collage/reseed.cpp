// SPDX-License-Identifier: Apache-2.0
#include "collage/reseed.h"

#include <algorithm>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/target.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

// The 8-connected regions of `mask` of at least `min_area` pixels, largest first; the stable
// sort keeps labels (row order) on ties, so the result is deterministic.
std::vector<ErrorRegion> regions(const cv::Mat& mask, int min_area) {
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<std::pair<int, int>> found;  // (area, label); label 0 is the background
  for (int k = 1; k < count; ++k)
    if (const int area = stats.at<int>(k, cv::CC_STAT_AREA); area >= min_area)
      found.emplace_back(area, k);
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<ErrorRegion> out;
  for (const auto& [area, label] : found) out.push_back({area, labels == label});
  return out;
}

cv::Mat opened(const cv::Mat& mask) {
  cv::Mat out;
  cv::morphologyEx(mask, out, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  return out;
}

}  // namespace

ErrorMaps error_maps(const cv::Mat& target, const cv::Mat& attractor, int min_area) {
  if (target.type() != CV_8UC1 || attractor.type() != CV_8UC1 ||
      target.size() != attractor.size() || target.rows != target.cols)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("error_maps: L and A must be square CV_8UC1 rasters of one size (got "
                            "{}x{} and {}x{})",
                            target.cols, target.rows, attractor.cols, attractor.rows));
  ErrorMaps maps;
  maps.missed = opened((target != 0) & (attractor == 0));
  maps.spilled = opened((target == 0) & (attractor != 0));
  maps.missed_regions = regions(maps.missed, min_area);
  maps.spilled_regions = regions(maps.spilled, min_area);
  return maps;
}

std::vector<int> least_paying(const AttractorLoss& loss, std::span<const AffineMap> maps) {
  if (maps.size() < 2) return {};
  std::vector<double> left(maps.size());
  std::vector<AffineMap> without(maps.begin() + 1, maps.end());
  for (std::size_t k = 0; k < maps.size(); ++k) {
    // `without` is maps less maps[k]: put maps[k - 1] back where maps[k] was taken out.
    if (k > 0) without[k - 1] = maps[k - 1];
    left[k] = loss.terms(without).iou;
  }
  std::vector<int> order(maps.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return left[static_cast<std::size_t>(a)] > left[static_cast<std::size_t>(b)];
  });
  return order;
}

std::vector<AffineMap> maps_onto_region(const cv::Mat& target, const cv::Mat& region,
                                        const SearchOptions& options, int min_pixels) {
  const cv::Mat piece = resampled_mask(region, target.cols, 0.5) & target;
  if (cv::countNonZero(piece) < min_pixels) return {};
  cv::Mat labels(target.size(), CV_32SC1, cv::Scalar(-1));
  labels.setTo(0, piece);
  std::vector<AffineMap> out;
  for (const auto& piece_maps : search_pieces(target, labels, 1, options))
    for (const Candidate& c : piece_maps) out.push_back(c.map);
  return out;
}

}  // namespace ifsfx::collage
