// SPDX-License-Identifier: Apache-2.0
#include "flame/render_camera.h"

#include <cmath>
#include <numbers>

namespace ifsfx::flame {

FlameRaster flame_raster(const Camera& camera, int supersample, int gutter) {
  FlameRaster r;
  r.width = camera.width;
  r.height = camera.height;
  r.supersample = supersample;
  r.gutter = gutter;
  r.bins_x = camera.width * supersample + 2 * gutter;
  r.bins_y = camera.height * supersample + 2 * gutter;
  r.ppu = camera.scale * std::exp2(camera.zoom);
  // The plotted point turns by +rotate about the centre, (x, y) ↦ (x·cos t − y·sin t,
  // x·sin t + y·cos t) in the y-down plane: clockwise on the screen, as flam3-render draws it
  // (tests/flame/render_test.cpp checks a one-point flame against it).
  const double t = camera.rotate * std::numbers::pi / 180;
  const double c = std::cos(t), s = std::sin(t);
  const double k = r.ppu * supersample;
  const double cx = camera.center.x, cy = camera.center.y;
  // bin = k·R·(p − centre) + (W·ss/2 + gutter, H·ss/2 + gutter)
  const double ox = camera.width * supersample / 2.0 + gutter;
  const double oy = camera.height * supersample / 2.0 + gutter;
  r.to_bins = {k * c, -k * s, k * s, k * c, ox - k * (c * cx - s * cy), oy - k * (s * cx + c * cy)};
  return r;
}

}  // namespace ifsfx::flame
