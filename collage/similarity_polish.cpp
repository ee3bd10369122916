// SPDX-License-Identifier: Apache-2.0
#include "collage/similarity_polish.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace ifsfx::collage::detail {

FineScene::FineScene(const cv::Mat& fine, int samples) : size_(fine.cols) {
  cv::distanceTransform(~fine, distance_, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const long count = cv::countNonZero(fine);
  const long stride = std::max(1L, (count + samples - 1) / std::max(1, samples));
  long k = 0;
  for (int r = 0; r < fine.rows; ++r)
    for (int c = 0; c < fine.cols; ++c)
      if (fine.at<std::uint8_t>(r, c) && k++ % stride == 0)
        points_.push_back({(c + 0.5) / size_, 1 - (r + 0.5) / size_});
}

double FineScene::precision(const AffineMap& w) const {
  double sum = 0;
  for (const Point& p : points_) {
    const Point q = w(p);
    const double c = std::floor(q.x * size_), r = std::floor((1 - q.y) * size_);
    if (c >= 0 && r >= 0 && c < size_ && r < size_)
      sum += std::max(0.0, 1.0 - distance_.at<float>(static_cast<int>(r), static_cast<int>(c)));
  }
  return sum / static_cast<double>(points_.size());
}

namespace {

Polished scored(const FineScene& scene, const AffineMap& w) {
  const double p = scene.precision(w);
  return {w, p, (std::abs(w.det()) + 0.01) * (10 * p - 9)};
}

// Compass direction k of 16 from w: each coefficient of the linear part ± `linear` (k < 8), the
// image of the centre ± `shift` along x and y (k < 12), the linear part scaled by 1 ± `linear`
// and turned by ± `linear` radians (a copy a few degrees or per cent off moves along one axis,
// not four). The linear part moves about the centre, which stays where w sends it.
AffineMap stepped(const AffineMap& w, int k, double linear, double shift, Point centre) {
  const double sign = k % 2 ? -1 : 1;
  if (k >= 8 && k < 12) {
    AffineMap moved = w;
    (k < 10 ? moved.e : moved.f) += sign * shift;
    return moved;
  }
  AffineMap m = w;
  if (k < 8) {
    std::array<double, 6> x = w.coefficients();
    x[static_cast<std::size_t>(k / 2)] += sign * linear;
    m = AffineMap::from_coefficients(x);
  } else if (k < 14) {
    const double f = 1 + sign * linear;
    m.a *= f, m.b *= f, m.c *= f, m.d *= f;
  } else {
    const double c = std::cos(sign * linear), s = std::sin(sign * linear);
    m = AffineMap{c, -s, s, c, 0, 0}.compose(w);
  }
  const Point at = w(centre), now = m(centre);
  m.e += at.x - now.x, m.f += at.y - now.y;
  return m;
}

}  // namespace

Polished polish(const FineScene& scene, const AffineMap& start, Point centre, double max_factor,
                int evaluations) {
  Polished best = scored(scene, start);
  int used = 1;
  double linear = 0.02, shift = 2.0 / scene.size();
  for (int halving = 0; halving <= 3 && used < evaluations; ++halving) {
    bool moved = true;
    while (moved && used < evaluations) {
      moved = false;
      for (int k = 0; k < 16 && used < evaluations; ++k) {
        const AffineMap w = stepped(best.map, k, linear, shift, centre);
        if (!(w.contraction() < max_factor)) continue;
        const Polished tried = scored(scene, w);
        ++used;
        if (tried.value > best.value) best = tried, moved = true;
      }
    }
    linear /= 2, shift /= 2;
  }
  return best;
}

std::vector<std::size_t> distinct(std::span<const AffineMap> maps, Point centre, double radius,
                                  double tolerance, std::size_t keep) {
  const std::array<Point, 5> probes = {
      centre, Point{centre.x + radius, centre.y}, Point{centre.x - radius, centre.y},
      Point{centre.x, centre.y + radius}, Point{centre.x, centre.y - radius}};
  const auto near = [&](const AffineMap& u, const AffineMap& v) {
    for (const Point& p : probes) {
      const Point a = u(p), b = v(p);
      if (std::hypot(a.x - b.x, a.y - b.y) > tolerance) return false;
    }
    return true;
  };
  // The kept maps by the cell of their image of the centre, so that only neighbours are compared.
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < maps.size() && kept.size() < keep; ++i) {
    const Point q = maps[i](centre);
    const long cx = std::lround(std::floor(q.x / tolerance));
    const long cy = std::lround(std::floor(q.y / tolerance));
    bool seen = false;
    for (long dx = -1; dx <= 1 && !seen; ++dx)
      for (long dy = -1; dy <= 1 && !seen; ++dy)
        for (std::size_t j : cells[{cx + dx, cy + dy}])
          if (near(maps[j], maps[i])) {
            seen = true;
            break;
          }
    if (seen) continue;
    kept.push_back(i);
    cells[{cx, cy}].push_back(i);
  }
  return kept;
}

}  // namespace ifsfx::collage::detail
