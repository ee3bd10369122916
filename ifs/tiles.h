// SPDX-License-Identifier: Apache-2.0
// Seamless tiles (docs/design.md §11): a seamless render is one period of a doubly periodic
// texture, the raster of its tile. The picture of several periods, and a picture that starts
// elsewhere in the period, are that raster repeated and shifted cyclically by whole pixels: pixel
// (c, r) shows the texture at tile pixel ((c + s.x) mod W, (r + s.y) mod H), the same point of the
// plane modulo the lattice of the tile. So a picture of K×L periods is the K×L repetition of the
// tile byte for byte, by construction (the same counts per pixel for the measure, the same
// addresses for tops and steal maps), whatever the mode.
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"

namespace ifsfx {

struct TileLayout {
  cv::Size tiles{1, 1};  // periods across and down in the picture, 1..64 each
  // Where the picture starts in the period, as fractions of the tile's width (right) and height
  // (down), each in [0, 1); rounded to whole pixels (tile_shift). {0, 0}: the view as it is.
  Point offset;
};

// A preset offered as a seamless tile says so in a [seamless] table (docs/seamless.md):
//   [seamless]
//   view = [x0, y0, x1, y1]  # optional: the tile; default: the preset's view, or its attractor
//   offset = [0.5, 0.5]      # optional: where the picture starts in the period (TileLayout)
struct SeamlessTile {
  std::optional<Box> view;
  Point offset;
};

// The shift in whole pixels of `offset` on a tile of `size` pixels: round(offset · size) mod size.
cv::Point tile_shift(cv::Size size, Point offset);

// Throws Error{invalid_argument} for tiles outside 1..64 a side, an offset outside [0, 1) or not a
// number, or a picture of more than 32768 pixels a side ("tiles: ...", "tile offset: ...").
void check_tile_layout(cv::Size tile, const TileLayout& layout);

// The picture of layout.tiles periods of the texture whose period is `tile` (any type), starting
// at layout.offset in it. Checks the layout (check_tile_layout).
//   cv::Mat wall = tile_picture(render_measure(fern, {256, 256}, {.seamless = true}),
//                               {.tiles = {3, 3}});
cv::Mat tile_picture(const cv::Mat& tile, const TileLayout& layout);

// The same for a steal map (its coordinates and coverage): applying it colours the picture.
StealMap tile_picture(const StealMap& tile, const TileLayout& layout);

}  // namespace ifsfx
