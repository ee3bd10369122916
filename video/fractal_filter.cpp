// SPDX-License-Identifier: Apache-2.0
#include "video/fractal_filter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/compact_remap.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::video {

namespace {

constexpr int band_rows = 32;  // rows per work chunk: fixed, so the split never depends on threads

// Far outside any source: with BORDER_TRANSPARENT the remap leaves such pixels untouched.
constexpr float outside = -16384.0f;

std::size_t bands(int rows) {
  return static_cast<std::size_t>((rows + band_rows - 1) / band_rows);
}

cv::Range band(std::size_t chunk, int rows) {
  const int r0 = static_cast<int>(chunk) * band_rows;
  return {r0, std::min(rows, r0 + band_rows)};
}

void check_frame(const cv::Mat& frame, const RemapTable& table) {
  if ((frame.type() != CV_8UC3 && frame.type() != CV_8UC4) || frame.size() != table.source_size)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("fractal filter: frame must be {}x{} 8-bit BGR or BGRA (got {}x{}, type {})",
                    table.source_size.width, table.source_size.height, frame.cols, frame.rows,
                    frame.type()));
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

// One band of output rows through one table, over the background already in `out`: through the
// compact table where it serves the frame (the covered pixels only, no OpenCV thread pool inside
// our bands), else cv::remap; the bytes are the same.
void remap_band(const cv::Mat& frame, const RemapTable& table, cv::Mat& out, cv::Range rows) {
  if (table.compact && detail::compact_remap_supports(frame.type()) && frame.isContinuous())
    return detail::remap_rows(*table.compact, frame, out, rows, std::nullopt);
  cv::Mat dst = out.rowRange(rows);
  const int mode =
      table.interpolation == Interpolation::nearest ? cv::INTER_NEAREST : cv::INTER_LINEAR;
  cv::remap(frame, dst, table.xy.rowRange(rows),
            table.fraction.empty() ? cv::Mat() : table.fraction.rowRange(rows), mode,
            cv::BORDER_TRANSPARENT);
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

RemapTable make_remap_table(const StealMap& map, cv::Size source_size, Interpolation interpolation,
                            int threads) {
  if (map.empty() || map.source_uv.type() != CV_32FC2 || map.coverage.type() != CV_8UC1 ||
      map.source_uv.size() != map.coverage.size())
    throw Error(ErrorKind::invalid_argument,
                "fractal filter: steal map must be CV_32FC2 coordinates with a CV_8UC1 coverage "
                "of the same size");
  if (source_size.width < 2 || source_size.height < 2)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("fractal filter: frames must be at least 2x2 (got {}x{})",
                            source_size.width, source_size.height));
  const cv::Size size = map.size();
  const float w = static_cast<float>(source_size.width);
  const float h = static_cast<float>(source_size.height);
  // The remap's fixed point has 1/32 pixel steps; staying a step inside the last column and row
  // keeps bilinear lookups of edge pixels within the source, where a transparent border would
  // otherwise drop them.
  const float x_max = w - 1.0f - 1.0f / 32;
  const float y_max = h - 1.0f - 1.0f / 32;
  RemapTable table;
  table.source_size = source_size;
  table.interpolation = interpolation;
  detail::fixed_point_maps(
      size, interpolation == Interpolation::nearest, threads,
      [&](int r, cv::Vec2f* out) {
        const auto* uv = map.source_uv.ptr<cv::Vec2f>(r);
        const auto* covered = map.coverage.ptr<std::uint8_t>(r);
        for (int c = 0; c < size.width; ++c) {
          if (covered[c] == 0 || !std::isfinite(uv[c][0]) || !std::isfinite(uv[c][1])) {
            out[c] = {outside, outside};
            continue;
          }
          out[c] = {std::clamp(uv[c][0] * w - 0.5f, 0.0f, x_max),
                    std::clamp(uv[c][1] * h - 0.5f, 0.0f, y_max)};
        }
      },
      table.xy, table.fraction);
  if (auto compact = detail::compact_remap(table.xy, table.fraction, source_size,
                                           detail::RemapBorder::transparent, threads))
    table.compact = std::make_shared<const detail::CompactRemap>(std::move(*compact));
  return table;
}

cv::Mat filter_frame(const cv::Mat& frame, const RemapTable& table, const FilterOptions& options) {
  cv::Mat out;
  filter_frame(frame, table, options, out);
  return out;
}

void filter_frame(const cv::Mat& input, const RemapTable& table, const FilterOptions& options,
                  cv::Mat& out) {
  check_frame(input, table);
  const cv::Mat frame = input.data == out.data ? input.clone() : input;  // in place
  check_filter_options(options);
  const cv::Size size = table.size();
  const cv::Mat original = needs_original(frame, options) ? original_at(frame, size) : cv::Mat();
  out.create(size, frame.type());
  parallel_for(bands(size.height), options.threads, [&](std::size_t chunk, int) {
    const cv::Range rows = band(chunk, size.height);
    fill_background(original, options, out, rows);
    remap_band(frame, table, out, rows);
    if (options.mix > 0) {
      cv::Mat dst = out.rowRange(rows);
      cv::addWeighted(dst, 1 - options.mix, original.rowRange(rows), options.mix, 0, dst);
    }
    pass_alpha(original, out, rows);
  });
}

cv::Mat filter_frame(const cv::Mat& frame, const RemapTable& from, const RemapTable& to, double t,
                     const FilterOptions& options) {
  cv::Mat out;
  filter_frame(frame, from, to, t, options, out);
  return out;
}

void filter_frame(const cv::Mat& input, const RemapTable& from, const RemapTable& to, double t,
                  const FilterOptions& options, cv::Mat& out) {
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
  parallel_for(bands(size.height), options.threads, [&](std::size_t chunk, int) {
    const cv::Range rows = band(chunk, size.height);
    fill_background(original, options, out, rows);
    fill_background(original, options, second, rows);
    remap_band(frame, from, out, rows);
    remap_band(frame, to, second, rows);
    cv::Mat dst = out.rowRange(rows);
    cv::addWeighted(dst, 1 - t, second.rowRange(rows), t, 0, dst);
    if (options.mix > 0)
      cv::addWeighted(dst, 1 - options.mix, original.rowRange(rows), options.mix, 0, dst);
    pass_alpha(original, out, rows);
  });
}

}  // namespace ifsfx::video
