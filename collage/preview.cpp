// SPDX-License-Identifier: Apache-2.0
#include "collage/preview.h"

#include <array>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "ifs/error.h"
#include "ifs/tops.h"

namespace ifsfx::collage {

namespace {

const cv::Vec3b kMissed(64, 64, 64);

// Pixels of `target` that `covered` leaves out in dark grey; coloured pixels outside the target
// (spill) at a third of their brightness.
void mark_misses(cv::Mat& panel, const cv::Mat& target, const cv::Mat& covered) {
  cv::Mat missed, spilled;
  cv::bitwise_and(target, covered == 0, missed);
  cv::bitwise_and(target == 0, covered, spilled);
  cv::Mat dim = panel / 3;
  dim.copyTo(panel, spilled);
  panel.setTo(kMissed, missed);
}

}  // namespace

cv::Vec3b piece_colour(int n) {
  // HSV with the hue a golden angle (≈ 137.5°) per piece; OpenCV's 8-bit hue is degrees / 2.
  const double hue = std::fmod(n * 137.50776405, 360.0);
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue / 2, 200, 255)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

cv::Mat fit_preview(const cv::Mat& target, const Ifs& ifs, const PreviewOptions& options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || target.empty())
    throw Error(ErrorKind::invalid_argument,
                "preview: the target must be a square CV_8UC1 working raster");
  if (options.scale < 1 || options.scale > 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("preview: scale must be in 1..16 (got {})", options.scale));
  validate(ifs, "preview");
  const int n = target.cols;

  cv::Mat shape(n, n, CV_8UC3, cv::Scalar::all(0));
  shape.setTo(cv::Scalar::all(255), target);

  cv::Mat collage(n, n, CV_8UC3, cv::Scalar::all(0));
  cv::Mat covered(n, n, CV_8UC1, cv::Scalar(0));
  for (std::size_t k = 0; k < ifs.maps.size(); ++k) {
    const std::array<AffineMap, 1> one = {ifs.maps[k]};
    const cv::Mat piece = collage_raster(target, one);
    collage.setTo(piece_colour(static_cast<int>(k)), piece);
    covered |= piece;
  }
  mark_misses(collage, target, covered);

  // By the chaos game at the fit's quality: the attractor as the fit measured it.
  const TopSymbols symbols = top_symbols(ifs, {n, n},
                                         {.sampling = {.view = Box{0, 0, 1, 1},
                                                       .quality = options.quality,
                                                       .seed = options.seed,
                                                       .threads = options.threads},
                                          .exact = false});
  cv::Mat attractor(n, n, CV_8UC3, cv::Scalar::all(0));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      if (symbols.coverage.at<std::uint8_t>(r, c))
        attractor.at<cv::Vec3b>(r, c) = piece_colour(symbols.first.at<std::uint16_t>(r, c));
  mark_misses(attractor, target, symbols.coverage);

  const int side = n * options.scale, gap = std::max(2, side / 32);
  cv::Mat out(side, 3 * side + 2 * gap, CV_8UC3, cv::Scalar::all(32));
  const cv::Mat* panels[] = {&shape, &collage, &attractor};
  for (int k = 0; k < 3; ++k) {
    cv::Mat big;
    cv::resize(*panels[k], big, {side, side}, 0, 0, cv::INTER_NEAREST);
    big.copyTo(out(cv::Rect(k * (side + gap), 0, side, side)));
  }
  return out;
}

}  // namespace ifsfx::collage
