// SPDX-License-Identifier: Apache-2.0
#include "tests/obs/yuv_reference.h"

#include <algorithm>
#include <cmath>

#include <media-io/video-io.h>

namespace ifsfx::obs_test {
namespace {

struct Matrix {
  float m[16], lo[3], hi[3];
  Matrix() { video_format_get_parameters(VIDEO_CS_709, VIDEO_RANGE_PARTIAL, m, lo, hi); }
};

std::uint8_t byte(double v) {
  return static_cast<std::uint8_t>(std::clamp(std::floor(v + 0.5), 0.0, 255.0));
}

}  // namespace

// rgb = M (y, u, v, 1) in [0, 1]: solved for (y, u, v) by Cramer's rule on M's 3×3 part.
Planes nv12_of(const cv::Mat& bgr) {
  const Matrix M;
  const cv::Matx33d A(M.m[0], M.m[1], M.m[2], M.m[4], M.m[5], M.m[6], M.m[8], M.m[9], M.m[10]);
  const cv::Vec3d offset(M.m[3], M.m[7], M.m[11]);
  const cv::Matx33d inverse = A.inv();
  auto yuv = [&](cv::Vec3d b) { return inverse * (cv::Vec3d(b[2], b[1], b[0]) / 255.0 - offset); };
  Planes p;
  p.format = VIDEO_FORMAT_NV12;
  p.planes = {cv::Mat(bgr.size(), CV_8UC1), cv::Mat(bgr.rows / 2, bgr.cols / 2, CV_8UC2)};
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x)
      p.planes[0].at<std::uint8_t>(y, x) = byte(255 * yuv(cv::Vec3d(bgr.at<cv::Vec3b>(y, x)))[0]);
  for (int y = 0; y < bgr.rows / 2; ++y)
    for (int x = 0; x < bgr.cols / 2; ++x) {
      cv::Vec3d mean(0, 0, 0);
      for (int d = 0; d < 4; ++d)
        mean += cv::Vec3d(bgr.at<cv::Vec3b>(2 * y + d / 2, 2 * x + d % 2));
      const cv::Vec3d c = 255 * yuv(mean / 4);
      p.planes[1].at<cv::Vec2b>(y, x) = {byte(c[1]), byte(c[2])};
    }
  return p;
}

cv::Mat bgr_of(const Planes& nv12) {
  const Matrix M;
  cv::Mat bgr(nv12.planes[0].size(), CV_8UC3);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec2b uv = nv12.planes[1].at<cv::Vec2b>(y / 2, x / 2);
      double v[3] = {nv12.planes[0].at<std::uint8_t>(y, x) / 255.0, uv[0] / 255.0, uv[1] / 255.0};
      for (int k = 0; k < 3; ++k) v[k] = std::clamp(v[k], double(M.lo[k]), double(M.hi[k]));
      double rgb[3];
      for (int c = 0; c < 3; ++c)
        rgb[c] = M.m[c * 4] * v[0] + M.m[c * 4 + 1] * v[1] + M.m[c * 4 + 2] * v[2] + M.m[c * 4 + 3];
      bgr.at<cv::Vec3b>(y, x) = {byte(255 * rgb[2]), byte(255 * rgb[1]), byte(255 * rgb[0])};
    }
  return bgr;
}

}  // namespace ifsfx::obs_test
