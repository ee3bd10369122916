// SPDX-License-Identifier: Apache-2.0
// The camera of a flame (flam3's `size`, `center`, `scale`, `zoom`, `rotate`) as a map from the
// flame plane to the bins of the supersampled histogram. The flame plane's y points down the
// picture (flame/flame.h): pixel column j, row i covers x ∈ [j, j + 1), y ∈ [i, i + 1) of
//   x_pix = (x' − cx)·ppu + W/2,   y_pix = (y' − cy)·ppu + H/2,   ppu = scale·2^zoom,
// where (x', y') is the point turned by `rotate` degrees about the centre (clockwise on screen); a
// bin is 1/ss of a pixel, and `gutter` bins surround the picture for the spatial filter to read.
#pragma once

#include "flame/flame.h"
#include "ifs/affine_map.h"

namespace ifsfx::flame {

struct FlameRaster {
  int width = 0, height = 0;   // output pixels
  int supersample = 1;         // bins per pixel side
  int gutter = 0;              // bins on each side beyond the picture
  int bins_x = 0, bins_y = 0;  // width·ss + 2·gutter, height·ss + 2·gutter
  double ppu = 0;              // pixels per flame-plane unit, zoom included
  AffineMap to_bins;  // flame plane → bin coordinates (bin (i, j) covers [j, j+1)×[i, i+1))
};

// The raster of `camera` with `supersample` bins per pixel and `gutter` bins of margin.
FlameRaster flame_raster(const Camera& camera, int supersample, int gutter);

}  // namespace ifsfx::flame
