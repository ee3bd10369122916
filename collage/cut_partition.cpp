// SPDX-License-Identifier: Apache-2.0
#include "collage/cut_partition.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "collage/initialise.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

// The position of each pixel of L (row-major order) along L's principal axis, pixels.
std::vector<double> along_axis(const cv::Mat& target) {
  double n = 0, mx = 0, my = 0;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) n += 1, mx += c, my += r;
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c))
        sxx += (c - mx) * (c - mx), sxy += (c - mx) * (r - my), syy += (r - my) * (r - my);
  // The eigenvector of the larger eigenvalue of [[sxx sxy][sxy syy]] is at this angle.
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  const double ux = std::cos(angle), uy = std::sin(angle);
  std::vector<double> t;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) t.push_back((c - mx) * ux + (r - my) * uy);
  return t;
}

}  // namespace

cv::Mat cut_partition(const cv::Mat& target, int n, double end, bool from_low) {
  if (n < 2 || !(end > 0 && end < 1))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("cut partition: needs n ≥ 2 and an end share in (0, 1) (got {}, {})", n, end));
  std::vector<double> t = along_axis(target);
  std::vector<double> sorted = t;
  std::sort(sorted.begin(), sorted.end());
  const auto k = static_cast<std::size_t>(end * static_cast<double>(sorted.size()));
  const double cut = from_low ? sorted[k] : sorted[sorted.size() - 1 - k];
  cv::Mat rest(target.size(), CV_8UC1, cv::Scalar(0));
  cv::Mat out(target.size(), CV_32SC1, cv::Scalar(-1));
  std::size_t i = 0;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) {
        const bool in_end = from_low ? t[i] < cut : t[i] > cut;
        if (in_end)
          rest.at<std::uint8_t>(r, c) = 255;
        else
          out.at<int>(r, c) = 0;
        ++i;
      }
  if (cv::countNonZero(rest) < n - 1)
    throw Error(ErrorKind::invalid_argument, "cut partition: the end is too small to split");
  const cv::Mat parts = partition(rest, n - 1, {.by_component = true});
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (parts.at<int>(r, c) >= 0) out.at<int>(r, c) = parts.at<int>(r, c) + 1;
  return out;
}

}  // namespace ifsfx::collage
