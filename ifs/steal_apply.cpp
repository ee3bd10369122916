// SPDX-License-Identifier: Apache-2.0
// apply: colouring an image through a steal map, one cv::remap (docs/design.md §3: T depends on F,
// G and the grid only, so a video filter prepares the map once and remaps every frame).
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/compact_remap.h"
#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/steal_map.h"

namespace ifsfx {

namespace {

constexpr int kBand = 64;  // rows a worker remaps at a time

void check_map(const StealMap& map) {
  if (map.empty())
    throw Error(ErrorKind::invalid_argument, "steal map: must not be empty (got 0×0)");
  if (map.source_uv.type() != CV_32FC2 || map.coverage.type() != CV_8UC1 ||
      map.source_uv.size() != map.coverage.size())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("steal map: needs CV_32FC2 coordinates and a CV_8UC1 coverage of one "
                            "size (got types {} and {}, {}x{} and {}x{})",
                            map.source_uv.type(), map.coverage.type(), map.source_uv.cols,
                            map.source_uv.rows, map.coverage.cols, map.coverage.rows));
}

void check_source(const cv::Mat& source) {
  if (source.empty()) throw Error(ErrorKind::invalid_argument, "source image: must not be empty");
  const int depth = source.depth();
  if ((depth != CV_8U && depth != CV_16U && depth != CV_16S && depth != CV_32F &&
       depth != CV_64F) ||
      source.channels() > 4)
    throw Error(ErrorKind::unsupported,
                fmt::format("source image: 1 to 4 channels of 8/16-bit integers or floats are "
                            "supported (got type {})",
                            source.type()));
  if (source.cols >= 32767 || source.rows >= 32767)
    throw Error(ErrorKind::unsupported,
                fmt::format("source image: sides below 32767 pixels are supported (got {}x{})",
                            source.cols, source.rows));
}

}  // namespace

PreparedStealMap prepare_apply(const StealMap& map, cv::Size source_size,
                               const ApplyOptions& options) {
  check_map(map);
  // A transparent border keeps a covered pixel a 1/32 pixel step inside the last column and row,
  // which needs a source of two pixels a side.
  const int smallest = options.border == RemapBorder::transparent ? 2 : 1;
  if (source_size.width < smallest || source_size.height < smallest || source_size.width >= 32767 ||
      source_size.height >= 32767)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("source size: {} to 32766 pixels a side{} (got {}x{})", smallest,
                            smallest == 2 ? " under a transparent border" : "", source_size.width,
                            source_size.height));
  // Normalised (u, v) to source pixels: (u·W − 0.5, v·H − 0.5). Covered pixels are clamped to the
  // image (the edge pixel is repeated, never mixed with what lies off it): under a constant border
  // onto the last column and row, under a transparent one a fixed-point step (1/32 pixel) inside
  // them, where cv::remap would otherwise leave the pixel untouched. Uncovered pixels, and any
  // whose point is not finite, are sent two pixels off the source, where the border decides.
  const float w = static_cast<float>(source_size.width), h = static_cast<float>(source_size.height);
  const float inside = options.border == RemapBorder::transparent ? 1.0f / 32 : 0.0f;
  const float x_max = w - 1 - inside, y_max = h - 1 - inside;
  PreparedStealMap out;
  out.source_size = source_size;
  out.options = options;
  const int width = map.size().width;
  detail::fixed_point_maps(
      map.size(), options.interpolation == Interpolation::nearest, options.threads,
      [&](int r, cv::Vec2f* out_row) {
        const auto* uv = map.source_uv.ptr<cv::Vec2f>(r);
        const auto* cov = map.coverage.ptr<std::uint8_t>(r);
        for (int c = 0; c < width; ++c)
          out_row[c] = cov[c] == 0 || !std::isfinite(uv[c][0]) || !std::isfinite(uv[c][1])
                           ? cv::Vec2f(-2, -2)
                           : cv::Vec2f(std::clamp(uv[c][0] * w - 0.5f, 0.0f, x_max),
                                       std::clamp(uv[c][1] * h - 0.5f, 0.0f, y_max));
      },
      out.xy, out.frac);
  if (auto compact =
          detail::compact_remap(out.xy, out.frac, source_size, options.border, options.threads))
    out.compact = std::make_shared<const detail::CompactRemap>(std::move(*compact));
  return out;
}

void check_apply_source(const PreparedStealMap& map, const cv::Mat& source) {
  check_source(source);
  if (source.size() != map.source_size)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("source image: must be the size the steal map was prepared for "
                    "({}x{}) (got {}x{})",
                    map.source_size.width, map.source_size.height, source.cols, source.rows));
}

void apply_rows(const PreparedStealMap& map, const cv::Mat& source, cv::Mat& out, cv::Range rows) {
  const bool constant = map.options.border == RemapBorder::constant;
  if (map.compact && detail::compact_remap_supports(source.type()) && source.isContinuous())
    return detail::remap_rows(*map.compact, source, out, rows,
                              constant ? std::optional(map.options.background) : std::nullopt);
  cv::Mat dst = out.rowRange(rows);
  cv::remap(
      source, dst, map.xy.rowRange(rows), map.frac.empty() ? cv::Mat() : map.frac.rowRange(rows),
      map.options.interpolation == Interpolation::nearest ? cv::INTER_NEAREST : cv::INTER_LINEAR,
      constant ? cv::BORDER_CONSTANT : cv::BORDER_TRANSPARENT, map.options.background);
}

void apply(const PreparedStealMap& map, const cv::Mat& source, cv::Mat& out) {
  check_apply_source(map, source);
  out.create(map.size(), source.type());
  const cv::Mat continuous = source.isContinuous() ? source : source.clone();
  // Bands of rows on our own workers: a fixed split, so the bytes never depend on the threads.
  parallel_rows(out.rows, kBand, map.options.threads,
                [&](cv::Range rows) { apply_rows(map, continuous, out, rows); });
}

cv::Mat apply(const StealMap& map, const cv::Mat& source, const ApplyOptions& options) {
  check_source(source);
  cv::Mat out;
  if (options.border == RemapBorder::transparent) out = cv::Mat::zeros(map.size(), source.type());
  apply(prepare_apply(map, source.size(), options), source, out);
  return out;
}

}  // namespace ifsfx
