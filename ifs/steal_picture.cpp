// SPDX-License-Identifier: Apache-2.0
#include "ifs/steal_picture.h"

#include <vector>

#include <opencv2/imgproc.hpp>

#include "ifs/sampling.h"

namespace ifsfx {

cv::Scalar background_scalar(const Rgb& colour, int depth) {
  const double full = depth == CV_8U ? 255.0 : depth == CV_16U ? 65535.0 : 1.0;
  return {colour.b * full, colour.g * full, colour.r * full, 0};
}

cv::Mat with_coverage_alpha(const cv::Mat& coloured, const cv::Mat& coverage, bool alpha) {
  if (!alpha) {
    if (coloured.channels() != 4) return coloured;
    cv::Mat bgr;
    cv::cvtColor(coloured, bgr, cv::COLOR_BGRA2BGR);
    return bgr;
  }
  if (coloured.channels() == 4) return coloured;  // the source's alpha, 0 off the attractor
  cv::Mat bgr = coloured;
  if (coloured.channels() == 1) cv::cvtColor(coloured, bgr, cv::COLOR_GRAY2BGR);
  cv::Mat a;
  const double full = bgr.depth() == CV_8U ? 1.0 : bgr.depth() == CV_16U ? 257.0 : 1.0 / 255;
  coverage.convertTo(a, bgr.depth(), full);
  std::vector<cv::Mat> planes;
  cv::split(bgr, planes);
  planes.push_back(a);
  cv::Mat out;
  cv::merge(planes, out);
  return out;
}

cv::Mat tops_picture(const Ifs& F, cv::Size size, const TopsOptions& options, const Rgb& background,
                     bool alpha, TopsPictureStats* stats) {
  TopsOptions tops = options;
  tops.sampling.view = framed_viewport(F, size, options.sampling).view;  // to report it
  std::uint64_t points = 0;
  const cv::Mat image = render_tops(F, size, tops, &points);  // BGRA float, alpha = coverage
  if (stats) *stats = {.view = *tops.sampling.view, .points = tops.exact ? 0 : points};
  return tops_picture(image, background, alpha, stats);
}

cv::Mat tops_picture(cv::Mat image, const Rgb& background, bool alpha, TopsPictureStats* stats) {
  cv::Mat coverage;
  cv::extractChannel(image, coverage, 3);
  if (stats) stats->coverage = cv::countNonZero(coverage) / static_cast<double>(image.total());
  image.setTo(background_scalar(background, CV_32F), coverage == 0);
  if (!alpha) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  return image;
}

}  // namespace ifsfx
