// SPDX-License-Identifier: Apache-2.0
#include "collage/distance.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

void check_pair(const cv::Mat& a, const cv::Mat& b) {
  if (a.type() != CV_8UC1 || b.type() != CV_8UC1 || a.size() != b.size())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("distance: two CV_8UC1 masks of one size are needed (got {}×{} and "
                            "{}×{})",
                            a.cols, a.rows, b.cols, b.rows));
}

// Mean and max of d(·, b) over the pixels of a.
cv::Vec2d mean_and_max(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat d = distance_to(b);
  double sum = 0, largest = 0;
  long count = 0;
  for (int r = 0; r < a.rows; ++r) {
    const auto* in = a.ptr<std::uint8_t>(r);
    const auto* dist = d.ptr<float>(r);
    for (int c = 0; c < a.cols; ++c)
      if (in[c]) {
        sum += dist[c];
        largest = std::max(largest, static_cast<double>(dist[c]));
        ++count;
      }
  }
  if (count == 0)
    throw Error(ErrorKind::invalid_argument, "distance: the mask is empty (no pixel is set)");
  return {sum / static_cast<double>(count), largest};
}

}  // namespace

cv::Mat distance_to(const cv::Mat& mask) {
  if (mask.type() != CV_8UC1)
    throw Error(ErrorKind::invalid_argument, "distance: a CV_8UC1 mask is needed");
  if (cv::countNonZero(mask) == 0)
    throw Error(ErrorKind::invalid_argument, "distance: the mask is empty (no pixel is set)");
  // distanceTransform measures to the nearest zero pixel: make the set the zeros. L2 with the
  // precise mask is the exact Euclidean transform (Felzenszwalb–Huttenlocher).
  cv::Mat outside = mask == 0;
  cv::Mat d;
  cv::distanceTransform(outside, d, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return d;
}

double distance_bound(const cv::Mat& distance, double qx, double qy) {
  const int n = distance.cols, m = distance.rows;
  const int c = std::clamp(static_cast<int>(std::floor(qx)), 0, n - 1);
  const int r = std::clamp(static_cast<int>(std::floor(qy)), 0, m - 1);
  return distance.at<float>(r, c) + std::hypot(qx - (c + 0.5), qy - (r + 0.5));
}

double interpolated_distance(const cv::Mat& distance, double qx, double qy) {
  const int n = distance.cols, m = distance.rows;
  const double x = qx - 0.5, y = qy - 0.5;  // centre-based coordinates
  if (!(x >= 0 && y >= 0 && x <= n - 1 && y <= m - 1)) return distance_bound(distance, qx, qy);
  const int c = std::min(static_cast<int>(x), n - 2), r = std::min(static_cast<int>(y), m - 2);
  const double u = x - c, v = y - r;
  const float* row0 = distance.ptr<float>(r);
  const float* row1 = distance.ptr<float>(r + 1);
  return (1 - v) * ((1 - u) * row0[c] + u * row0[c + 1]) +
         v * ((1 - u) * row1[c] + u * row1[c + 1]);
}

double directed_hausdorff(const cv::Mat& a, const cv::Mat& b) {
  check_pair(a, b);
  return mean_and_max(a, b)[1];
}

double hausdorff(const cv::Mat& a, const cv::Mat& b) {
  check_pair(a, b);
  return std::max(mean_and_max(a, b)[1], mean_and_max(b, a)[1]);
}

double chamfer(const cv::Mat& a, const cv::Mat& b) {
  check_pair(a, b);
  return 0.5 * (mean_and_max(a, b)[0] + mean_and_max(b, a)[0]);
}

double iou(const cv::Mat& a, const cv::Mat& b) {
  check_pair(a, b);
  cv::Mat both, either;
  cv::bitwise_and(a != 0, b != 0, both);
  cv::bitwise_or(a != 0, b != 0, either);
  const int u = cv::countNonZero(either);
  return u == 0 ? 1.0 : static_cast<double>(cv::countNonZero(both)) / u;
}

}  // namespace ifsfx::collage
