// SPDX-License-Identifier: Apache-2.0
#include "run/seamless_options.h"

#include <cstdio>

#include <fmt/format.h>

#include "ifs/error.h"
#include "run/arguments.h"

namespace ifsfx::app {

TileLayout tile_layout(const SeamlessArgs& args, const std::optional<SeamlessTile>& preset,
                       cv::Size tile) {
  if (!args.seamless) {
    if (!args.tiles.empty())
      throw Error(ErrorKind::invalid_argument, "--tiles: only with --seamless");
    if (!args.offset.empty())
      throw Error(ErrorKind::invalid_argument, "--tile-offset: only with --seamless");
    return {};
  }
  TileLayout layout;
  if (!args.tiles.empty()) layout.tiles = parse_size(args.tiles, "--tiles");
  if (!args.offset.empty()) {
    double x = 0, y = 0;
    char tail = 0;
    if (std::sscanf(args.offset.c_str(), "%lf,%lf%c", &x, &y, &tail) != 2)
      throw Error(
          ErrorKind::parse,
          fmt::format("--tile-offset: must be X,Y, fractions of the tile (got '{}')", args.offset));
    layout.offset = {x, y};
  } else if (preset) {
    layout.offset = preset->offset;
  }
  check_tile_layout(tile, layout);
  return layout;
}

cv::Mat laid_out(const cv::Mat& tile, const TileLayout& layout) {
  if (layout.tiles == cv::Size(1, 1) && layout.offset == Point{}) return tile;
  return tile_picture(tile, layout);
}

std::vector<std::pair<std::string, std::string>> seamless_metadata(const Box& tile,
                                                                   const TileLayout& layout) {
  return {
      {"ifsfx:seamless_tile", fmt::format("{},{},{},{}", tile.x0, tile.y0, tile.x1, tile.y1)},
      {"ifsfx:tiles", fmt::format("{}x{}", layout.tiles.width, layout.tiles.height)},
      {"ifsfx:tile_offset", fmt::format("{},{}", layout.offset.x, layout.offset.y)},
  };
}

}  // namespace ifsfx::app
