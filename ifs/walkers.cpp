// SPDX-License-Identifier: Apache-2.0
#include "ifs/detail/walkers.h"

#include <cmath>

namespace ifsfx::detail {

WalkTables::WalkTables(const Ifs& ifs, const Viewport& viewport, int burn_in, int key_bits)
    : pick_(effective_probabilities(ifs)) {
  // On the torus of the tile (docs/design.md §11) the walkers live in tile coordinates, where the
  // wrap is t − ⌊t⌋: each map seen there, Φ⁻¹ ∘ f_n ∘ Φ, and pixels at (u·W, v·H).
  const AffineMap phi = viewport.tile_to_plane();
  const AffineMap phi_inv = *phi.inverse(0);
  for (const auto& f : ifs.maps) {
    const AffineMap m = viewport.wrap ? phi_inv.compose(f).compose(phi) : f;
    a_.push_back(m.a), b_.push_back(m.b), c_.push_back(m.c);
    d_.push_back(m.d), e_.push_back(m.e), f_.push_back(m.f);
  }
  const MapPicker::View pick = pick_.view();
  // The viewport's plane → pixel transform has no rotation: px = sx·x + ox, py = sy·y + oy.
  const AffineMap to_pixel = viewport.wrap
                                 ? AffineMap{static_cast<double>(viewport.size.width),  0, 0,
                                             static_cast<double>(viewport.size.height), 0, 0}
                                 : viewport.plane_to_pixel();
  spec_.maps = static_cast<std::uint32_t>(ifs.size());
  spec_.a = a_.data(), spec_.b = b_.data(), spec_.c = c_.data();
  spec_.d = d_.data(), spec_.e = e_.data(), spec_.f = f_.data();
  spec_.pick_n = pick.n;
  spec_.threshold = pick.threshold;
  spec_.alias = pick.alias;
  spec_.sx = to_pixel.a, spec_.ox = to_pixel.e;
  spec_.sy = to_pixel.d, spec_.oy = to_pixel.f;
  spec_.width = viewport.size.width;
  spec_.height = viewport.size.height;
  spec_.stride = viewport.size.width;
  spec_.burn_in = burn_in;
  spec_.key_bits = key_bits;
  spec_.wrap = viewport.wrap ? 1 : 0;
  const std::size_t n = ifs.size();
  palette_.assign(n, 0);
  for (std::size_t i = 0; i < n && n > 1; ++i)
    palette_[i] = static_cast<std::uint32_t>(
        std::lround(65535.0 * static_cast<double>(i) / static_cast<double>(n - 1)));
  spec_.palette = palette_.data();
}

}  // namespace ifsfx::detail
