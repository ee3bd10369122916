// SPDX-License-Identifier: Apache-2.0
// An affine IFS as a flame (flame_write.h).
#include <algorithm>

#include "flame/flame_write.h"
#include "flame/variations.h"
#include "ifs/render.h"
#include "ifs/view.h"

namespace ifsfx::flame {
namespace {

// f conjugated by S(x, y) = (x, −y): S∘f∘S, the same map seen in the flame plane (y down).
AffineMap flipped(const AffineMap& m) {
  return {m.a, -m.b, -m.c, m.d, m.e, -m.f};
}

// ifsfx's palette at coordinate t: the IFS's colours (map n at n/(N−1)) interpolated, or the ramp.
Rgb colour_at(const Ifs& ifs, double t) {
  if (ifs.colours.empty()) return palette_ramp(t);
  if (ifs.colours.size() == 1) return ifs.colours[0];
  const double pos = t * static_cast<double>(ifs.colours.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(pos), ifs.colours.size() - 2);
  const double w = pos - static_cast<double>(i);
  const Rgb& p = ifs.colours[i];
  const Rgb& q = ifs.colours[i + 1];
  return {p.r + w * (q.r - p.r), p.g + w * (q.g - p.g), p.b + w * (q.b - p.b)};
}

}  // namespace

Flame flame_from_ifs(const Ifs& ifs, const FlameFromIfsOptions& options) {
  validate(ifs, ifs.name.empty() ? "ifs" : ifs.name, {.allow_expansive = true});
  Flame f;
  f.name = ifs.name;
  const std::vector<double> p = effective_probabilities(ifs);
  const std::uint32_t linear = find_variation("linear")->id;
  const std::size_t n = ifs.size();
  for (std::size_t i = 0; i < n; ++i) {
    f.xforms.push_back({.pre = flipped(ifs.maps[i]),
                        .weight = p[i],
                        .colour = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0,
                        .colour_speed = 0.5,
                        .variations = {{.id = linear, .weight = 1}}});
  }
  const Viewport vp = framed_viewport(ifs, options.size, options.sampling);
  f.camera.width = options.size.width;
  f.camera.height = options.size.height;
  f.camera.center = {(vp.view.x0 + vp.view.x1) / 2, -(vp.view.y0 + vp.view.y1) / 2};
  f.camera.scale =
      std::min(options.size.width / vp.view.width(), options.size.height / vp.view.height());
  for (std::size_t k = 0; k < 256; ++k) {
    const Rgb c = colour_at(ifs, static_cast<double>(k) / 255);
    f.palette.colours[k] = {c.r, c.g, c.b, 1};
  }
  f.palette.mode = PaletteMode::linear;
  f.quality = options.sampling.quality;
  f.tone.brightness = options.brightness;
  f.tone.gamma = options.gamma;
  f.filtering.estimator_radius = 0;  // ifsfx's measure has no density estimation
  return f;
}

}  // namespace ifsfx::flame
