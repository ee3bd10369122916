// SPDX-License-Identifier: Apache-2.0
#include "collage/similarity_cover.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "collage/target.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

// Each copy's image w(L) on the raster, and what of it leaves L grown by a pixel.
struct Image {
  cv::Mat inside;  // w(L) ∩ L, CV_8UC1 0/255
  double spill = 0;
};

std::vector<Image> images(const cv::Mat& l, std::span<const SelfCopy> copies) {
  cv::Mat grown;
  cv::dilate(l, grown, cv::Mat::ones(3, 3, CV_8UC1));
  std::vector<Image> out;
  for (const SelfCopy& copy : copies) {
    const std::array<AffineMap, 1> one = {copy.map};
    const cv::Mat w = collage_raster(l, one);
    out.push_back({w & l, static_cast<double>(cv::countNonZero(w & ~grown))});
  }
  return out;
}

double gain(const Image& image, const cv::Mat& uncovered, const CoverOptions& o) {
  const double fresh = cv::countNonZero(image.inside & uncovered);
  const double again = cv::countNonZero(image.inside) - fresh;
  return fresh - o.spill * image.spill - o.overlap * again;
}

// The copy of best gain not yet chosen, or the `rank`-th best (0-based).
std::size_t pick(const std::vector<Image>& all, const cv::Mat& uncovered,
                 const std::vector<std::size_t>& chosen, const CoverOptions& o, int rank) {
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (std::find(chosen.begin(), chosen.end(), i) == chosen.end())
      ranked.emplace_back(gain(all[i], uncovered, o), i);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  return ranked[static_cast<std::size_t>(std::min<int>(rank, std::ssize(ranked) - 1))].second;
}

}  // namespace

std::vector<std::vector<AffineMap>> greedy_covers(const cv::Mat& target,
                                                  std::span<const SelfCopy> copies,
                                                  const CoverOptions& options) {
  if (options.maps < 1 || options.covers < 1 || !(options.spill >= 0) || !(options.overlap >= 0))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("greedy cover: needs maps, covers ≥ 1, spill and overlap ≥ 0 (got {}, {}, "
                    "{}, {})",
                    options.maps, options.covers, options.spill, options.overlap));
  if (std::ssize(copies) < options.maps) return {};
  const cv::Mat l = resampled_mask(target, std::min(options.size, target.cols));
  const std::vector<Image> all = images(l, copies);
  std::vector<std::vector<std::size_t>> seen;
  std::vector<std::vector<AffineMap>> covers;
  for (int k = 0; k < options.covers; ++k) {
    cv::Mat uncovered = l.clone();
    std::vector<std::size_t> chosen;
    for (int n = 0; n < options.maps; ++n) {
      const std::size_t i = pick(all, uncovered, chosen, options, n == 0 ? k : 0);
      chosen.push_back(i);
      uncovered &= ~all[i].inside;
    }
    std::vector<std::size_t> key = chosen;
    std::sort(key.begin(), key.end());
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
    seen.push_back(key);
    std::vector<AffineMap> maps;
    for (std::size_t i : chosen) maps.push_back(copies[i].map);
    covers.push_back(std::move(maps));
  }
  return covers;
}

}  // namespace ifsfx::collage
