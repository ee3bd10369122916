// SPDX-License-Identifier: Apache-2.0
// The exact top-address descent (docs/design.md §3): τ(x) = n · τ(f_n⁻¹(x)) with
// n = max{i : f_i⁻¹(x) ∈ A} (the tops rule of eq. 7: the higher map is on top), followed from each
// pixel centre in double precision through a conservative raster of the attractor A.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "ifs/detail/address_raster.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::detail {

namespace {

constexpr int kMaxMaskSide = 4096;
constexpr int kMaskPad = 3;  // mask pixels around the attractor's bounding box
constexpr int kMaxLevels = 128;

// A map of F seen from mask pixel coordinates: the inverse of f_n when it has one, else the
// pseudo-inverse of a singular map (a line or a point piece, like the fern's stem), whose piece
// has no area: x lies on it when f_n(f_n⁺(x)) is within a pixel of x.
struct Preimage {
  AffineMap inverse;
  std::optional<AffineMap> forward;  // set for singular maps only
};

AffineMap pseudo_inverse(const AffineMap& f) {
  // Rank one: M = σ u vᵀ, M⁺ = Mᵀ / σ² with σ² = ‖M‖_F²; rank zero: M⁺ = 0.
  const double frob = f.a * f.a + f.b * f.b + f.c * f.c + f.d * f.d;
  if (!(frob > 0)) return {0, 0, 0, 0, 0, 0};
  const AffineMap m{f.a / frob, f.c / frob, f.b / frob, f.d / frob, 0, 0};
  return {m.a, m.b, m.c, m.d, -(m.a * f.e + m.b * f.f), -(m.c * f.e + m.d * f.f)};
}

// The mask grid: the output grid's pixel size, extended over A's bounding box so that every
// preimage can be looked up, coarser only when that would exceed kMaxMaskSide pixels.
Viewport mask_viewport(const Box& bounds, const Viewport& out) {
  double pw = out.view.width() / out.size.width, ph = out.view.height() / out.size.height;
  const double bw = std::max(bounds.width(), 1e-9 * std::max(1.0, bounds.height()));
  const double bh = std::max(bounds.height(), 1e-9 * std::max(1.0, bounds.width()));
  const double scale = std::max(
      {1.0, (bw / pw + 2 * kMaskPad) / kMaxMaskSide, (bh / ph + 2 * kMaskPad) / kMaxMaskSide});
  pw *= scale;
  ph *= scale;
  // Aligned with the output grid when not rescaled, so coverage matches pixel for pixel.
  const double c0 = std::floor((bounds.x0 - out.view.x0) / pw) - kMaskPad;
  const double c1 = std::ceil((bounds.x1 - out.view.x0) / pw) + kMaskPad;
  const double r0 = std::floor((out.view.y1 - bounds.y1) / ph) - kMaskPad;
  const double r1 = std::ceil((out.view.y1 - bounds.y0) / ph) + kMaskPad;
  Viewport vp;
  vp.view = {out.view.x0 + c0 * pw, out.view.y1 - r1 * ph, out.view.x0 + c1 * pw,
             out.view.y1 - r0 * ph};
  vp.size = {static_cast<int>(c1 - c0), static_cast<int>(r1 - r0)};
  return vp;
}

// The attractor as a raster on the mask grid `mvp`: the pixels that chaos-game points reached,
// holes closed by the coverage policy. A pixel is set when it meets A, so the raster is already a
// conservative cover of A (the design's warning about erosion is for raster warps iterated with
// nearest lookups, which this is not). Dilating it further would let a higher map take points
// whose preimage lies up to a pixel outside A and shift every piece boundary by that much: the
// identity oracle sees it at once.
cv::Mat attractor_raster(const Ifs& F, const Viewport& mvp, const DescentOptions& options,
                         ChaosTopsStats* mask_stats) {
  return chaos_tops(F, mvp,
                    {.quality = options.quality,
                     .seed = options.seed,
                     .threads = options.threads,
                     .key_bits = 64,  // full keys: the Hutchinson passes need precise points
                     .cancel = options.cancel},
                    mask_stats)
      .coverage();
}

// The maps in mask pixel coordinates: h_n = P ∘ f_n⁻¹ ∘ P⁻¹.
std::vector<Preimage> mask_preimages(const Ifs& F, const AffineMap& to_mask) {
  const AffineMap from_mask = *to_mask.inverse(0);
  std::vector<Preimage> pre(F.size());
  for (std::size_t n = 0; n < F.size(); ++n) {
    const AffineMap f = to_mask.compose(F.maps[n]).compose(from_mask);
    if (auto inv = F.maps[n].inverse()) {
      pre[n].inverse = to_mask.compose(*inv).compose(from_mask);
    } else {
      pre[n].inverse = pseudo_inverse(f);
      pre[n].forward = f;
    }
  }
  return pre;
}

// What the descent of each pixel reads: the attractor's raster on its mask grid, and F's maps
// seen from the mask's pixel coordinates.
struct Mask {
  Viewport viewport;
  cv::Mat attractor;
  AffineMap to_mask;  // plane to mask pixel
  std::vector<Preimage> pre;

  bool inside(Point p) const {
    return p.x >= 0 && p.x < viewport.size.width && p.y >= 0 && p.y < viewport.size.height;
  }
  bool on_attractor(Point p) const {
    return inside(p) && attractor.at<std::uint8_t>(static_cast<int>(p.y), static_cast<int>(p.x));
  }
  double distance_outside(Point p) const {
    const double fw = viewport.size.width, fh = viewport.size.height;
    const double dx = std::max({0.0, -p.x, p.x - fw}), dy = std::max({0.0, -p.y, p.y - fh});
    return dx * dx + dy * dy;
  }
};

using Address = std::array<std::uint32_t, kMaxLevels>;

// One symbol of the top address of mask point x (eq. 7): the highest map whose piece holds x,
// with x's preimage under it; false when no piece holds x.
bool top_symbol(const Mask& mask, Point x, int& chosen, Point& next) {
  for (int n = static_cast<int>(mask.pre.size()) - 1; n >= 0; --n) {
    const Preimage& m = mask.pre[static_cast<std::size_t>(n)];
    const Point p = m.inverse(x);
    if (m.forward) {
      // A piece without area: x is on it when it is within a pixel of its own image.
      const Point back = (*m.forward)(p);
      if (std::hypot(back.x - x.x, back.y - x.y) > 0.75 || !mask.on_attractor(back)) continue;
    } else if (!mask.on_attractor(p)) {
      continue;
    }
    chosen = n;
    next = p;
    return true;
  }
  return false;
}

// The first `levels` symbols of the top address of mask point x, which lies on the attractor.
void descend(const Mask& mask, Point x, int levels, Address& sigma) {
  for (int level = 0; level < levels; ++level) {
    int chosen = -1;
    Point next{};
    if (!top_symbol(mask, x, chosen, next)) {
      // Outside every piece by rounding or at the mask's edge: take the preimage closest to the
      // mask so that x stays bounded (inverse maps expand).
      double best = INFINITY;
      for (int n = static_cast<int>(mask.pre.size()) - 1; n >= 0; --n) {
        const Point p = mask.pre[static_cast<std::size_t>(n)].inverse(x);
        const double dist = mask.distance_outside(p);
        if (dist < best) best = dist, chosen = n, next = p;
      }
      // Every preimage overflowed (maps that nearly collapse the plane expand it by 1e11 and
      // more a level): the address ends here, repeating its last symbol.
      if (chosen < 0) {
        chosen = level > 0 ? static_cast<int>(sigma[static_cast<std::size_t>(level - 1)]) : 0;
        next = x;
      }
    }
    sigma[static_cast<std::size_t>(level)] = static_cast<std::uint32_t>(chosen);
    x = next;
  }
}

// T(x) = g_σ1 ∘ … ∘ g_σL(c), c the fixed point of g_σL (a point of G's attractor), as (u, v).
cv::Vec2f colour_point(const Ifs& G, const Address& sigma, int levels) {
  Point y = fixed_point(G.maps[sigma[static_cast<std::size_t>(levels - 1)]]);
  for (int level = levels - 1; level >= 0; --level)
    y = G.maps[sigma[static_cast<std::size_t>(level)]](y);
  return {static_cast<float>(y.x), static_cast<float>(1 - y.y)};
}

// An output of `viewport`'s size with no pixel covered yet (and T's raster when G is given).
Descent empty_descent(const Ifs& F, const Ifs* G, const Viewport& viewport) {
  Descent out;
  out.tops.viewport = viewport;
  out.tops.bits = symbol_bits(F.size());
  out.tops.keys.assign(static_cast<std::size_t>(viewport.size.area()), 0);
  if (G) out.uv = cv::Mat(viewport.size, CV_32FC2, cv::Scalar::all(0));
  return out;
}

// The top address of each pixel centre of `viewport` (and T(x) with G), by bands of rows.
void descend_pixels(const Ifs* G, const Mask& mask, const Viewport& viewport, int levels,
                    const DescentOptions& options, Descent& out) {
  const int key_symbols = std::min(levels, out.tops.symbols());
  const int bits = out.tops.bits;
  const AffineMap out_to_mask = mask.to_mask.compose(*viewport.plane_to_pixel().inverse(0));
  constexpr int kBand = 8;
  parallel_rows(viewport.size.height, kBand, options.threads, [&](cv::Range rows) {
    Address sigma{};
    for (int row = rows.start; row < rows.end; ++row) {
      options.cancel.check("exact descent");  // a row is W·L·N lookups at most
      for (int col = 0; col < viewport.size.width; ++col) {
        // The pixel centre, exact, in mask pixel coordinates.
        const Point x = out_to_mask(Point{col + 0.5, row + 0.5});
        if (!mask.on_attractor(x)) continue;
        descend(mask, x, levels, sigma);
        std::uint64_t key = 0;
        for (int k = 0; k < key_symbols; ++k)
          key |= std::uint64_t{sigma[static_cast<std::size_t>(k)]} << (64 - bits * (k + 1));
        out.tops.keys[static_cast<std::size_t>(row) * viewport.size.width + col] = key | 1;
        if (G) out.uv.at<cv::Vec2f>(row, col) = colour_point(*G, sigma, levels);
      }
    }
  });
}

}  // namespace

Descent exact_descent(const Ifs& F, const Ifs* G, const Viewport& viewport,
                      const DescentOptions& options, ChaosTopsStats* mask_stats) {
  const int levels = std::clamp(options.levels, 1, kMaxLevels);
  // 1. The attractor as a raster (a conservative cover of A).
  Mask mask;
  mask.viewport = mask_viewport(attractor_bounds(F, options.seed, options.cancel), viewport);
  mask.attractor = attractor_raster(F, mask.viewport, options, mask_stats);
  // 2. The maps in mask pixel coordinates.
  mask.to_mask = mask.viewport.plane_to_pixel();
  mask.pre = mask_preimages(F, mask.to_mask);
  // 3. The descent from each pixel centre.
  Descent out = empty_descent(F, G, viewport);
  descend_pixels(G, mask, viewport, levels, options, out);
  return out;
}

}  // namespace ifsfx::detail
