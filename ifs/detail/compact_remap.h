// SPDX-License-Identifier: Apache-2.0
// A cv::remap table in OpenCV's own fixed point (CV_16SC2 pixel + 1/32-pixel fraction), compacted
// to the output pixels that read the source: per output row, runs of such pixels, each with its
// source pixel and bilinear weights. Pixels that read nothing are not stored: they are filled
// with a background, or left as they are. Remapping through it gives the bytes cv::remap gives
// (tests/ifs/compact_remap_test.cpp compares them), but skips the pixels off the attractor, uses
// no OpenCV thread pool inside our workers, and so scales with the cores a caller gives it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/steal_map.h"  // RemapBorder

namespace ifsfx::detail {

struct CompactRemap {
  struct Run {
    int begin = 0, end = 0;  // output columns [begin, end)
  };
  cv::Size size;         // output pixels
  cv::Size source_size;  // source pixels the table reads
  bool bilinear = true;
  std::vector<std::uint32_t> row_runs;     // rows+1 offsets into runs
  std::vector<std::uint32_t> row_entries;  // rows+1 offsets into pixel / weight
  std::vector<Run> runs;
  std::vector<std::uint32_t> pixel;   // top-left source pixel, y·W + x
  std::vector<std::uint16_t> weight;  // fy·33 + fx with fx, fy in 0..32 (see compact_remap.cpp)
};

// OpenCV's fixed-point remap tables of a float map that `fill_row(r, out)` writes a row at a time
// (the source pixel (x, y) that each output pixel of row r reads): cv::convertMaps(…, CV_16SC2,
// nearest) on fixed bands of rows on `threads` workers (0 = all cores), which gives the bytes of
// one call over the whole map for any thread count. `xy` becomes CV_16SC2 of `size`, `frac`
// CV_16UC1 of `size` (empty for nearest).
void fixed_point_maps(cv::Size size, bool nearest, int threads,
                      const std::function<void(int row, cv::Vec2f* out)>& fill_row, cv::Mat& xy,
                      cv::Mat& frac);

// Compacts the maps cv::convertMaps(…, CV_16SC2, nearest) made: `xy` CV_16SC2, `frac` CV_16UC1
// (empty for nearest). Returns nothing where the table needs cv::remap's general border handling:
// a source below 2×2, or (constant border) a bilinear square partly on the source. Bands of rows
// on `threads` workers (0 = all cores); the table is the same for any count.
std::optional<CompactRemap> compact_remap(const cv::Mat& xy, const cv::Mat& frac,
                                          cv::Size source_size, RemapBorder border,
                                          int threads = 1);

// Whether remap_rows handles this source type (8-bit, 1 to 4 channels).
bool compact_remap_supports(int type);

// Output rows `rows` of cv::remap(source, out, xy, frac, …): `out` is table.size and the source's
// type, `source` is table.source_size. With a background, the pixels that read nothing get it
// (BORDER_CONSTANT); without, they are left as they are (BORDER_TRANSPARENT).
void remap_rows(const CompactRemap& table, const cv::Mat& source, cv::Mat& out, cv::Range rows,
                const std::optional<cv::Scalar>& background);

}  // namespace ifsfx::detail
