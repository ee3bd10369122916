// SPDX-License-Identifier: Apache-2.0
// The seamless-tile options of `ifsfx render` and `ifsfx texture` (docs/seamless.md):
// --seamless (the picture is one period of a doubly periodic texture: the IFS or superIFS on the
// torus of the tile), --tiles KxL (the picture of K×L periods) and --tile-offset X,Y (where the
// picture starts in the period).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/tiles.h"

namespace ifsfx::app {

struct SeamlessArgs {
  bool seamless = false;
  std::string tiles;   // "KxL"; empty: 1x1
  std::string offset;  // "X,Y"; empty: the preset's [seamless] offset, else 0,0
};

// The picture's layout for a tile of `tile` pixels: --tiles and --tile-offset (the offset by
// default the preset's), checked (check_tile_layout); both refused without --seamless.
TileLayout tile_layout(const SeamlessArgs& args, const std::optional<SeamlessTile>& preset,
                       cv::Size tile);

// The picture of `layout` from the tile: tile_picture, or the tile itself for one period at 0,0.
cv::Mat laid_out(const cv::Mat& tile, const TileLayout& layout);

// Image metadata of a seamless render: the tile, the periods and the offset.
std::vector<std::pair<std::string, std::string>> seamless_metadata(const Box& tile,
                                                                   const TileLayout& layout);

}  // namespace ifsfx::app
