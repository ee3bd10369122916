// SPDX-License-Identifier: Apache-2.0
#include "ifs/tiles.h"

#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/view.h"

namespace ifsfx {

namespace {

constexpr int kMaxTiles = 64;

int shift_of(int pixels, double fraction) {
  const auto s = static_cast<long>(std::lround(fraction * pixels)) % pixels;
  return static_cast<int>(s);
}

}  // namespace

cv::Point tile_shift(cv::Size size, Point offset) {
  return {shift_of(size.width, offset.x), shift_of(size.height, offset.y)};
}

void check_tile_layout(cv::Size tile, const TileLayout& layout) {
  const cv::Size k = layout.tiles;
  if (k.width < 1 || k.height < 1 || k.width > kMaxTiles || k.height > kMaxTiles)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("tiles: must be 1 to {} periods a side (got {}x{})", kMaxTiles, k.width,
                            k.height));
  for (const double f : {layout.offset.x, layout.offset.y})
    if (!(f >= 0 && f < 1))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("tile offset: must be fractions of the tile in [0, 1) (got {},{})",
                              layout.offset.x, layout.offset.y));
  check_size(tile, "tile");
  check_size({tile.width * k.width, tile.height * k.height}, "size × tiles");
}

cv::Mat tile_picture(const cv::Mat& tile, const TileLayout& layout) {
  check_tile_layout(tile.size(), layout);
  const cv::Point s = tile_shift(tile.size(), layout.offset);
  const int w = tile.cols, h = tile.rows;
  cv::Mat out(h * layout.tiles.height, w * layout.tiles.width, tile.type());
  const std::size_t pixel = tile.elemSize();
  for (int r = 0; r < out.rows; ++r) {
    const std::uint8_t* src = tile.ptr<std::uint8_t>((r + s.y) % h);
    std::uint8_t* dst = out.ptr<std::uint8_t>(r);
    // One row of the picture: the tile's row from column s.x to its end, then from its start.
    for (int c = 0; c < out.cols;) {
      const int from = (c + s.x) % w, run = std::min(w - from, out.cols - c);
      std::memcpy(dst + static_cast<std::size_t>(c) * pixel,
                  src + static_cast<std::size_t>(from) * pixel,
                  static_cast<std::size_t>(run) * pixel);
      c += run;
    }
  }
  return out;
}

StealMap tile_picture(const StealMap& tile, const TileLayout& layout) {
  return {tile_picture(tile.source_uv, layout), tile_picture(tile.coverage, layout)};
}

}  // namespace ifsfx
