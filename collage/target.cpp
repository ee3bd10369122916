// SPDX-License-Identifier: Apache-2.0
#include "collage/target.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"

namespace ifsfx::collage {

namespace {

// One channel of `image` as CV_32F in [0, 1] (integer depths scaled by their full scale).
cv::Mat unit_float(const cv::Mat& channel) {
  cv::Mat out;
  switch (channel.depth()) {
    case CV_8U:
      channel.convertTo(out, CV_32F, 1.0 / 255);
      break;
    case CV_16U:
      channel.convertTo(out, CV_32F, 1.0 / 65535);
      break;
    default:
      channel.convertTo(out, CV_32F);
      break;
  }
  return out;
}

cv::Mat grey_of(const cv::Mat& image) {
  cv::Mat colour = unit_float(image);  // convertTo keeps the channels
  if (colour.channels() == 1) return colour;
  if (colour.channels() == 2) {  // grey + alpha
    cv::Mat grey;
    cv::extractChannel(colour, grey, 0);
    return grey;
  }
  cv::Mat bgr = colour;
  if (colour.channels() == 4) cv::cvtColor(colour, bgr, cv::COLOR_BGRA2BGR);
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace

cv::Mat shape_mask(const cv::Mat& image, const TargetOptions& options, const std::string& what) {
  if (image.empty())
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: the image is empty", what));
  const int channels = image.channels();
  if (channels < 1 || channels > 4)
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: images of 1 to 4 channels are supported (got {})", what, channels));
  if (options.threshold && !(*options.threshold >= 0 && *options.threshold <= 1))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("threshold: must be in [0, 1] (got {})", *options.threshold));

  const bool has_alpha = channels == 2 || channels == 4;
  cv::Mat mask;
  std::string rule;
  if (has_alpha) {
    // The shape is where the image is opaque.
    cv::Mat alpha;
    cv::extractChannel(image, alpha, channels - 1);
    const double t = options.threshold.value_or(0.5);
    cv::compare(unit_float(alpha), t, mask, options.invert ? cv::CMP_LE : cv::CMP_GT);
    rule = fmt::format("alpha {} {:.3g}", options.invert ? "≤" : ">", t);
  } else {
    const cv::Mat grey = grey_of(image);
    double t = 0;
    const cv::CmpTypes side = options.invert ? cv::CMP_GT : cv::CMP_LE;
    if (options.threshold) {
      t = *options.threshold;
      cv::compare(grey, t, mask, side);
    } else {
      // Otsu's threshold on an 8-bit copy (256 levels are plenty to split two populations),
      // compared on that copy: Otsu returns the last level of the dark class.
      cv::Mat grey8, unused;
      grey.convertTo(grey8, CV_8U, 255);
      const double t8 = cv::threshold(grey8, unused, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
      cv::compare(grey8, t8, mask, side);
      t = t8 / 255;
    }
    rule = fmt::format("grey {} {:.3g}{}", options.invert ? ">" : "≤", t,
                       options.threshold ? "" : " (Otsu)");
  }

  const int inside = cv::countNonZero(mask);
  if (inside == 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the shape is empty: no pixel has {} (try invert or threshold)",
                            what, rule));
  if (inside == static_cast<int>(mask.total()))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the shape is the whole image: every pixel has {} (try invert or "
                            "threshold)",
                            what, rule));
  return mask;
}

cv::Mat load_target(const std::filesystem::path& path, const TargetOptions& options) {
  return shape_mask(read_image(path).pixels, options, path.string());
}

cv::Mat working_raster(const cv::Mat& mask, const FrameOptions& options) {
  if (options.size < 8 || options.size > 2048)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("size: the working raster's side must be in 8..2048 (got {})", options.size));
  if (!(options.margin >= 0 && options.margin < 0.5))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("margin: must be in [0, 0.5) (got {})", options.margin));
  if (mask.type() != CV_8UC1 || cv::countNonZero(mask) == 0)
    throw Error(ErrorKind::invalid_argument,
                "target: the shape mask must be a non-empty CV_8UC1 mask");

  const cv::Rect box = cv::boundingRect(mask);
  // Side of the square frame in target pixels: the box's longer side plus the margin both ways.
  const double side = std::max(box.width, box.height) / (1 - 2 * options.margin);
  const auto frame_side = static_cast<int>(std::ceil(side));
  const int x0 = box.x + box.width / 2 - frame_side / 2;
  const int y0 = box.y + box.height / 2 - frame_side / 2;

  // Copy the shape into a square frame of background, whatever part of it the image holds.
  cv::Mat frame(frame_side, frame_side, CV_8UC1, cv::Scalar(0));
  const cv::Rect src =
      cv::Rect(x0, y0, frame_side, frame_side) & cv::Rect(0, 0, mask.cols, mask.rows);
  mask(src).copyTo(frame(cv::Rect(src.x - x0, src.y - y0, src.width, src.height)));

  cv::Mat coverage;
  const cv::Size size(options.size, options.size);
  cv::resize(frame, coverage, size, 0, 0,
             frame_side > options.size ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::Mat raster;
  cv::threshold(coverage, raster, 127, 255, cv::THRESH_BINARY);
  if (cv::countNonZero(raster) == 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("target: the shape vanishes on a {}×{} working raster (it is too thin "
                            "or too small; try a larger size)",
                            options.size, options.size));
  return raster;
}

cv::Mat resampled_mask(const cv::Mat& mask, int size, double keep) {
  if (size == mask.cols) return mask > 0;
  cv::Mat coverage, raster;
  cv::resize(mask, coverage, {size, size}, 0, 0, cv::INTER_AREA);
  // INTER_AREA rounds a mean of 0/255 values: any cover of at least 1/510 shows as ≥ 1.
  cv::threshold(coverage, raster, std::floor(keep * 255), 255, cv::THRESH_BINARY);
  return raster;
}

}  // namespace ifsfx::collage
