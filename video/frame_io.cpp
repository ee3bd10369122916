// SPDX-License-Identifier: Apache-2.0
#include "video/frame_io.h"

#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

extern "C" {
#include <libavutil/rational.h>
}

#include "ifs/error.h"

namespace ifsfx::video {

Rational rate_from_fps(double fps) {
  if (!(fps > 0) || !std::isfinite(fps) || fps > 1e6) return {0, 1};
  if (std::abs(fps - std::round(fps)) < 1e-6) return {static_cast<int>(std::lround(fps)), 1};
  // 30000/1001 and its kin, as written to two or three decimals (29.97, 23.976).
  const double ntsc = fps * 1.001;
  if (std::abs(ntsc - std::round(ntsc)) < 1e-4 * fps)
    return {static_cast<int>(std::lround(ntsc)) * 1000, 1001};
  const AVRational q = av_d2q(fps, 1000000);
  return {q.num, q.den};
}

cv::Mat to_bgr8(const cv::Mat& image) {
  cv::Mat eight;
  switch (image.depth()) {
    case CV_8U:
      eight = image;
      break;
    case CV_16U:
      image.convertTo(eight, CV_8U, 1.0 / 257);
      break;
    default:
      image.convertTo(eight, CV_8U, 255);
      break;
  }
  cv::Mat bgr;
  switch (eight.channels()) {
    case 1:
      cv::cvtColor(eight, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 4:
      cv::cvtColor(eight, bgr, cv::COLOR_BGRA2BGR);
      break;
    case 3:
      bgr = eight;
      break;
    default:
      throw Error(ErrorKind::unsupported,
                  fmt::format("image: {} channels are not a colour image", eight.channels()));
  }
  return bgr;
}

}  // namespace ifsfx::video
