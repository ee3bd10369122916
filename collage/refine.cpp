// SPDX-License-Identifier: Apache-2.0
#include "collage/refine.h"

#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

// For every pixel, the (col, row) of the nearest set pixel of `mask` (approximate Euclidean
// metric, exact enough to pair points).
class Nearest {
 public:
  explicit Nearest(const cv::Mat& mask) {
    cv::Mat dist;
    cv::distanceTransform(mask == 0, dist, labels_, cv::DIST_L2, cv::DIST_MASK_5,
                          cv::DIST_LABEL_PIXEL);
    int largest = 0;
    for (int r = 0; r < mask.rows; ++r)
      for (int c = 0; c < mask.cols; ++c)
        if (mask.at<std::uint8_t>(r, c)) largest = std::max(largest, labels_.at<int>(r, c));
    where_.assign(static_cast<std::size_t>(largest) + 1, cv::Point(-1, -1));
    for (int r = 0; r < mask.rows; ++r)
      for (int c = 0; c < mask.cols; ++c)
        if (mask.at<std::uint8_t>(r, c))
          where_[static_cast<std::size_t>(labels_.at<int>(r, c))] = {c, r};
  }
  cv::Point operator()(int col, int row) const {
    return where_[static_cast<std::size_t>(labels_.at<int>(row, col))];
  }

 private:
  cv::Mat labels_;
  std::vector<cv::Point> where_;
};

// Normal equations of the least-squares affine fit p → t (pixel coordinates).
struct Pairs {
  std::array<double, 9> ata{};  // Σ u uᵀ, u = (x, y, 1)
  std::array<double, 3> atx{}, aty{};
  long count = 0;
  void add(double px, double py, double tx, double ty) {
    const double u[3] = {px, py, 1};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) ata[static_cast<std::size_t>(3 * i + j)] += u[i] * u[j];
      atx[static_cast<std::size_t>(i)] += u[i] * tx;
      aty[static_cast<std::size_t>(i)] += u[i] * ty;
    }
    ++count;
  }
};

}  // namespace

std::vector<AffineMap> refine_icp(const cv::Mat& target, std::vector<AffineMap> maps,
                                  const RefineOptions& options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "refine: the target must be a non-empty square CV_8UC1 working raster");
  const int n = target.cols;
  const AffineMap to_pixel = plane_to_pixel(n);
  const AffineMap to_plane = *to_pixel.inverse();
  const Nearest nearest_in_l(target);
  std::vector<cv::Point> l_pixels;
  cv::findNonZero(target, l_pixels);

  for (int round = 0; round < options.iterations; ++round) {
    options.cancel.check("fit");
    if (std::chrono::steady_clock::now() >= options.deadline) break;
    std::vector<Pairs> pairs(maps.size());
    // Image points binned by pixel: the one nearest the pixel's centre stands for the pixel.
    cv::Mat occupied(n, n, CV_8UC1, cv::Scalar(0));
    cv::Mat owner(n, n, CV_32SC2, cv::Scalar(-1, -1));  // (map, index into l_pixels)
    cv::Mat offset(n, n, CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
    for (std::size_t k = 0; k < maps.size(); ++k) {
      const AffineMap m = to_pixel.compose(maps[k].compose(to_plane));
      for (std::size_t i = 0; i < l_pixels.size(); ++i) {
        const double px = l_pixels[i].x + 0.5, py = l_pixels[i].y + 0.5;
        const Point q = m({px, py});
        const int c = std::clamp(static_cast<int>(std::floor(q.x)), 0, n - 1);
        const int r = std::clamp(static_cast<int>(std::floor(q.y)), 0, n - 1);
        // Forward pair: f_k(p) → the centre of L nearest to it.
        const cv::Point t = nearest_in_l(c, r);
        pairs[k].add(px, py, t.x + 0.5, t.y + 0.5);
        if (q.x < 0 || q.y < 0 || q.x >= n || q.y >= n) continue;
        const auto d = static_cast<float>(std::hypot(q.x - (c + 0.5), q.y - (r + 0.5)));
        if (d < offset.at<float>(r, c)) {
          offset.at<float>(r, c) = d;
          owner.at<cv::Vec2i>(r, c) = {static_cast<int>(k), static_cast<int>(i)};
          occupied.at<std::uint8_t>(r, c) = 255;
        }
      }
    }
    // Reverse pairs: each centre t of L with the image point nearest to it.
    if (cv::countNonZero(occupied) > 0) {
      const Nearest nearest_image(occupied);
      for (const auto& t : l_pixels) {
        const cv::Point g = nearest_image(t.x, t.y);
        const cv::Vec2i who = owner.at<cv::Vec2i>(g.y, g.x);
        const cv::Point p = l_pixels[static_cast<std::size_t>(who[1])];
        pairs[static_cast<std::size_t>(who[0])].add(p.x + 0.5, p.y + 0.5, t.x + 0.5, t.y + 0.5);
      }
    }
    // Solve per map; keep the old map where the fit is ill-posed or not contractive enough.
    for (std::size_t k = 0; k < maps.size(); ++k) {
      if (pairs[k].count < 3) continue;
      const cv::Matx33d a(pairs[k].ata.data());
      cv::Matx31d row_x, row_y;
      if (!cv::solve(a, cv::Matx31d(pairs[k].atx.data()), row_x, cv::DECOMP_CHOLESKY) ||
          !cv::solve(a, cv::Matx31d(pairs[k].aty.data()), row_y, cv::DECOMP_CHOLESKY))
        continue;
      const AffineMap pixel_fit{row_x(0), row_x(1), row_y(0), row_y(1), row_x(2), row_y(2)};
      const AffineMap plane_fit = to_plane.compose(pixel_fit.compose(to_pixel));
      if (plane_fit.finite() && plane_fit.contraction() < options.max_factor) maps[k] = plane_fit;
    }
  }
  return maps;
}

}  // namespace ifsfx::collage
