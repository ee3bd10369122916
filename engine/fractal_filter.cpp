// SPDX-License-Identifier: Apache-2.0
#include "engine/fractal_filter.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::engine {

namespace {

constexpr int band_rows = 32;  // rows per work chunk: fixed, so the split never depends on threads

// The precondition of the remap (check_apply_source), and the filter's own: a table with a
// transparent border over 8-bit BGR or BGRA frames.
void check_frame(const cv::Mat& frame, const PreparedStealMap& table) {
  check_apply_source(table, frame);
  if (table.options.border != RemapBorder::transparent)
    throw Error(ErrorKind::invalid_argument,
                "fractal filter: needs a map prepared with a transparent border (got constant)");
  if (frame.type() != CV_8UC3 && frame.type() != CV_8UC4)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("fractal filter: frame must be 8-bit BGR or BGRA (got type {})", frame.type()));
}

// The original frame is needed at the output size for the mix, the original background and the
// alpha channel passed through.
bool needs_original(const cv::Mat& frame, const FilterOptions& options) {
  return options.mix > 0 || options.background.kind == BackgroundKind::original ||
         frame.channels() == 4;
}

// Alpha is not stolen: the output's fourth channel is the original's, pixel for pixel.
void pass_alpha(const cv::Mat& original, cv::Mat& out, cv::Range rows) {
  if (out.channels() != 4) return;
  const cv::Mat src = original.rowRange(rows);
  cv::Mat dst = out.rowRange(rows);
  const int from_to[] = {3, 3};
  cv::mixChannels(&src, 1, &dst, 1, from_to, 1);
}

// The background and the original frame at the output size, as each band needs them.
cv::Mat original_at(const cv::Mat& frame, cv::Size size) {
  if (frame.size() == size) return frame;
  cv::Mat resized;
  cv::resize(frame, resized, size, 0, 0, cv::INTER_AREA);
  return resized;
}

void fill_background(const cv::Mat& original, const FilterOptions& options, cv::Mat& out,
                     cv::Range rows) {
  cv::Mat dst = out.rowRange(rows);
  if (options.background.kind == BackgroundKind::original)
    original.rowRange(rows).copyTo(dst);
  else
    dst.setTo(options.background.colour);
}

}  // namespace

void check_filter_options(const FilterOptions& options) {
  if (!(options.mix >= 0 && options.mix <= 1))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("mix: must be in [0, 1] (got {})", options.mix));
}

Background parse_background(const std::string& text, const std::string& what) {
  if (text == "black") return {BackgroundKind::colour, cv::Scalar::all(0)};
  if (text == "white") return {BackgroundKind::colour, cv::Scalar::all(255)};
  if (text == "original") return {BackgroundKind::original, cv::Scalar::all(0)};
  unsigned r = 0, g = 0, b = 0;
  char tail = 0;
  if (text.size() == 7 && text[0] == '#' &&
      std::sscanf(text.c_str(), "#%2x%2x%2x%c", &r, &g, &b, &tail) == 3)
    return {BackgroundKind::colour, cv::Scalar(b, g, r)};
  if (std::sscanf(text.c_str(), "%u,%u,%u%c", &r, &g, &b, &tail) == 3 && r < 256 && g < 256 &&
      b < 256)
    return {BackgroundKind::colour, cv::Scalar(b, g, r)};
  throw Error(
      ErrorKind::parse,
      fmt::format("{}: expected black, white, original, #rrggbb or R,G,B (got '{}')", what, text));
}

PreparedStealMap prepare_filter(const StealMap& map, cv::Size frame_size,
                                Interpolation interpolation, int threads) {
  return prepare_apply(
      map, frame_size,
      {.interpolation = interpolation, .border = RemapBorder::transparent, .threads = threads});
}

cv::Mat filter_frame(const cv::Mat& frame, const PreparedStealMap& table,
                     const FilterOptions& options) {
  cv::Mat out;
  filter_frame(frame, table, options, out);
  return out;
}

void filter_frame(const cv::Mat& input, const PreparedStealMap& table, const FilterOptions& options,
                  cv::Mat& out) {
  check_frame(input, table);
  const cv::Mat frame = input.data == out.data ? input.clone() : input;  // in place
  check_filter_options(options);
  const cv::Size size = table.size();
  const cv::Mat original = needs_original(frame, options) ? original_at(frame, size) : cv::Mat();
  out.create(size, frame.type());
  parallel_rows(size.height, band_rows, options.threads, [&](cv::Range rows) {
    fill_background(original, options, out, rows);
    apply_rows(table, frame, out, rows);
    if (options.mix > 0) {
      cv::Mat dst = out.rowRange(rows);
      cv::addWeighted(dst, 1 - options.mix, original.rowRange(rows), options.mix, 0, dst);
    }
    pass_alpha(original, out, rows);
  });
}

cv::Mat filter_frame(const cv::Mat& frame, const PreparedStealMap& from, const PreparedStealMap& to,
                     double t, const FilterOptions& options) {
  cv::Mat out;
  filter_frame(frame, from, to, t, options, out);
  return out;
}

void filter_frame(const cv::Mat& input, const PreparedStealMap& from, const PreparedStealMap& to,
                  double t, const FilterOptions& options, cv::Mat& out) {
  check_frame(input, from);
  check_frame(input, to);
  const cv::Mat frame = input.data == out.data ? input.clone() : input;  // in place
  check_filter_options(options);
  if (from.size() != to.size())
    throw Error(ErrorKind::invalid_argument, "fractal filter: cross-faded maps differ in size");
  if (t <= 0) return filter_frame(frame, from, options, out);
  if (t >= 1) return filter_frame(frame, to, options, out);
  const cv::Size size = from.size();
  const cv::Mat original = needs_original(frame, options) ? original_at(frame, size) : cv::Mat();
  out.create(size, frame.type());
  cv::Mat second(size, frame.type());
  parallel_rows(size.height, band_rows, options.threads, [&](cv::Range rows) {
    fill_background(original, options, out, rows);
    fill_background(original, options, second, rows);
    apply_rows(from, frame, out, rows);
    apply_rows(to, frame, second, rows);
    cv::Mat dst = out.rowRange(rows);
    cv::addWeighted(dst, 1 - t, second.rowRange(rows), t, 0, dst);
    if (options.mix > 0)
      cv::addWeighted(dst, 1 - options.mix, original.rowRange(rows), options.mix, 0, dst);
    pass_alpha(original, out, rows);
  });
}

}  // namespace ifsfx::engine
