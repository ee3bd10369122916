// SPDX-License-Identifier: Apache-2.0
// compute_steal_map: T(x) = π_G(τ_F(x)) per output pixel (paper §4, docs/design.md §3), by the
// chaos game (tops with address keys, then G applied to each pixel's winning address) or exactly
// (the per-pixel descent).
#include "ifs/steal_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "ifs/detail/address_raster.h"
#include "ifs/detail/preconditions.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx {

namespace detail {

Point fixed_point(const AffineMap& g) {
  const AffineMap i_minus_m{1 - g.a, -g.b, -g.c, 1 - g.d, 0, 0};
  if (auto inv = i_minus_m.inverse()) return (*inv)(Point{g.e, g.f});
  return {0.5, 0.5};
}

double word_contraction(const Ifs& G) {
  double best = G.contraction();
  std::vector<AffineMap> words(G.maps);
  for (int k = 2; k <= 3 && words.size() * G.size() <= 4096; ++k) {
    std::vector<AffineMap> longer;
    double s = 0;
    for (const auto& w : words)
      for (const auto& g : G.maps) {
        longer.push_back(w.compose(g));
        s = std::max(s, longer.back().contraction());
      }
    best = std::min(best, std::pow(s, 1.0 / k));
    words = std::move(longer);
  }
  return best;
}

int levels_for(double contraction) {
  if (!(contraction < 1)) return 128;
  if (!(contraction > 0)) return 1;
  return std::clamp(static_cast<int>(std::ceil(-20 * std::log(2.0) / std::log(contraction))), 1,
                    128);
}

namespace {

// Φ: the affine map of F's attractor box `fb` onto G's `gb`, a degenerate side (a line
// attractor) onto the middle of G's.
AffineMap box_onto_box(const Box& fb, const Box& gb) {
  const Point centre{0.5 * (gb.x0 + gb.x1), 0.5 * (gb.y0 + gb.y1)};
  const auto scale = [](double from, double to) { return from > 0 ? to / from : 0.0; };
  const double phi_x = scale(fb.width(), gb.width()), phi_y = scale(fb.height(), gb.height());
  return {phi_x,
          0,
          0,
          phi_y,
          centre.x - phi_x * 0.5 * (fb.x0 + fb.x1),
          centre.y - phi_y * 0.5 * (fb.y0 + fb.y1)};
}

// f_σ⁻¹ on the torus of the tile (docs/design.md §11), in pixel coordinates: x ← f_σ⁻¹(x + λ)
// for the first translate of x by the lattice, λ = (i·W, j·H), whose preimage lies in the tile
// (else the one nearest to it).
class TorusPreimage {
 public:
  explicit TorusPreimage(const Ifs& F, const Viewport& vp)
      : width_(vp.size.width), height_(vp.size.height) {
    const AffineMap to_pixel = vp.plane_to_pixel(), from_pixel = *to_pixel.inverse(0);
    for (const AffineMap& f : F.maps) {
      const AffineMap h = to_pixel.compose(f).compose(from_pixel);
      inverse_.push_back(h.inverse());
      Box b{INFINITY, INFINITY, -INFINITY, -INFINITY};
      for (const Point c :
           {Point{0, 0}, Point{width_, 0}, Point{0, height_}, Point{width_, height_}}) {
        const Point p = h(c);
        b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
      }
      piece_.push_back(b);
    }
  }

  Point operator()(std::uint32_t sigma, Point x) const {
    const AffineMap& inv = *inverse_[sigma];
    const Box& b = piece_[sigma];
    Point best = inv(x);
    double best_d = INFINITY;
    for (double i = std::ceil((b.x0 - x.x) / width_); i <= std::floor((b.x1 - x.x) / width_); ++i)
      for (double j = std::ceil((b.y0 - x.y) / height_); j <= std::floor((b.y1 - x.y) / height_);
           ++j) {
        const Point p = inv(Point{x.x + i * width_, x.y + j * height_});
        const double dx = std::max({0.0, -p.x, p.x - width_}),
                     dy = std::max({0.0, -p.y, p.y - height_});
        if (dx * dx + dy * dy < best_d) best_d = dx * dx + dy * dy, best = p;
        if (best_d == 0) return best;
      }
    return best;
  }

 private:
  double width_, height_;
  std::vector<std::optional<AffineMap>> inverse_;
  std::vector<Box> piece_;  // f_σ of the tile, in pixel coordinates
};

// T at a pixel's centre from its top address. The pixel's winning point x is the one with the
// largest address in the pixel, so it sits at an extreme of the pixel (towards the higher maps'
// side): evaluating T at x itself would shift the whole picture by up to a pixel. Instead the
// address is cut after the first m symbols w = σ1 … σm, where the piece f_w(A) holding x has
// shrunk to about the pixel, and T at the pixel centre x_c is taken from T(x) = g_w(T(f_w⁻¹(x)))
// on that piece, with T inside approximated by Φ, the affine map of F's attractor box onto G's:
// T(x_c) ≈ g_w(Φ(f_w⁻¹(x_c))). The error is a fraction of the piece g_w(R), about a pixel, but
// without the bias of the winning point; it vanishes when Φ = T (F = G: the identity oracle,
// whatever the pixel grid). Where w holds a singular map (no f_w⁻¹), the centre of g_w(R) is
// used instead.
class AddressCut {
 public:
  AddressCut(const AddressRaster& tops, const Ifs& F, const Ifs& G)
      : tops_(tops),
        F_(F),
        G_(G),
        n_(static_cast<std::uint32_t>(G.size())),
        // On the torus of the tile (docs/design.md §11) A lies in the tile: Φ maps the tile onto
        // G's box.
        torus_(tops.viewport.wrap),
        pixel_(std::min(tops.viewport.view.width() / tops.viewport.size.width,
                        tops.viewport.view.height() / tops.viewport.size.height)),
        from_pixel_(*tops.viewport.plane_to_pixel().inverse(0)),
        torus_preimage_(F, tops.viewport) {
    const Box fb = torus_ ? tops.viewport.view : attractor_bounds(F);
    extent_ = std::max(fb.width(), fb.height());
    // Per-map shrink factors of F (maps of factor ≥ 1 that contract in pairs count at F's word
    // rate).
    const double word = word_contraction(F);
    for (const AffineMap& f : F.maps) {
      const double s = f.contraction();
      factor_.push_back(s < 1 ? s : std::min(word, 0.999));
      singular_.push_back(!f.inverse().has_value());
    }
    const Box gb = attractor_bounds(G);
    centre_ = {0.5 * (gb.x0 + gb.x1), 0.5 * (gb.y0 + gb.y1)};
    phi_ = box_onto_box(fb, gb);
  }

  // T(x_c) for pixel (col, row), whose top address is `key` (nonzero).
  Point operator()(std::uint64_t key, int col, int row) const {
    AffineMap f_w, g_w;  // identities, then f_σ1 ∘ … ∘ f_σm and g_σ1 ∘ … ∘ g_σm
    bool invertible = true;
    double size = extent_;
    int symbols_used = 0;
    for (int m = 0; m < tops_.symbols() && size > 1.01 * pixel_; ++m, ++symbols_used) {
      const std::uint32_t sigma = symbol(key, m);
      size *= factor_[sigma];
      invertible = invertible && !singular_[sigma];
      f_w = f_w.compose(F_.maps[sigma]);
      g_w = g_w.compose(G_.maps[sigma]);
    }
    if (torus_) {
      if (!invertible) return g_w(centre_);
      Point x{col + 0.5, static_cast<double>(row) + 0.5};
      for (int m = 0; m < symbols_used; ++m) x = torus_preimage_(symbol(key, m), x);
      return g_w(phi_(from_pixel_(x)));
    }
    std::optional<AffineMap> f_inv;
    if (invertible) f_inv = f_w.inverse(0);
    return f_inv ? g_w(phi_((*f_inv)(tops_.viewport.pixel_centre(col, row)))) : g_w(centre_);
  }

 private:
  std::uint32_t symbol(std::uint64_t key, int m) const {
    return std::min(tops_.symbol(key, m), n_ - 1);
  }

  const AddressRaster& tops_;
  const Ifs& F_;
  const Ifs& G_;
  std::uint32_t n_;
  bool torus_;
  double pixel_, extent_ = 0;
  AffineMap from_pixel_, phi_;
  TorusPreimage torus_preimage_;
  std::vector<double> factor_;
  std::vector<bool> singular_;
  Point centre_;
};

}  // namespace

cv::Mat uv_from_keys(const AddressRaster& tops, const Ifs& F, const Ifs& G, int threads) {
  const AddressCut T(tops, F, G);
  cv::Mat uv(tops.viewport.size, CV_32FC2, cv::Scalar::all(0));
  const std::size_t rows = static_cast<std::size_t>(uv.rows);
  parallel_for(rows, threads, [&](std::size_t r, int) {
    const int row = static_cast<int>(r);
    auto* out = uv.ptr<cv::Vec2f>(row);
    for (int col = 0; col < uv.cols; ++col) {
      const std::uint64_t key = tops.at(col, row);
      if (key == 0) continue;
      const Point y = T(key, col, row);
      out[col] = cv::Vec2f(static_cast<float>(y.x), static_cast<float>(1 - y.y));
    }
  });
  return uv;
}

}  // namespace detail

StealMap compute_steal_map(const Ifs& F, const Ifs& G, cv::Size size,
                           const StealMapOptions& options, StealMapStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  detail::check_chaos_game({.ifs = F,
                            .name = F.name.empty() ? "drawing IFS" : F.name,
                            .contracting = true,
                            .size = size,
                            .sampling = &options.sampling});
  detail::check_chaos_game(
      {.ifs = G, .name = G.name.empty() ? "colouring IFS" : G.name, .contracting = true});
  if (G.size() != F.size())
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("colouring IFS: must have as many maps as the drawing IFS (got {} "
                            "for {})",
                            G.size(), F.size()));
  const Viewport viewport = framed_viewport(F, size, options.sampling);
  StealMap map;
  StealMapStats s;
  s.view = viewport.view;
  detail::ChaosTopsStats chaos;
  if (options.exact) {
    const int levels = detail::levels_for(detail::word_contraction(G));
    auto descent = detail::exact_descent(F, &G, viewport,
                                         {.levels = levels,
                                          .quality = 4,
                                          .seed = options.sampling.seed,
                                          .threads = options.sampling.threads,
                                          .cancel = options.sampling.cancel},
                                         &chaos);
    map.source_uv = std::move(descent.uv);
    map.coverage = descent.tops.coverage();
    s.levels = levels;
  } else {
    // 32-bit pixel records (half the memory traffic of the kernel) when their 32/b symbols pin
    // T down to 1/8192 of the source through G; else the full 64 bits.
    const int bits = detail::symbol_bits(G.size());
    const bool short_keys = std::pow(detail::word_contraction(G), 32 / bits) * 8192 <= 1;
    const auto tops = detail::chaos_tops(F, viewport,
                                         {.quality = options.sampling.quality,
                                          .seed = options.sampling.seed,
                                          .threads = options.sampling.threads,
                                          .key_bits = short_keys ? 32 : 64,
                                          .cancel = options.sampling.cancel},
                                         &chaos);
    options.sampling.cancel.check("steal map");
    map.source_uv = detail::uv_from_keys(tops, F, G, options.sampling.threads);
    map.coverage = tops.coverage();
    s.levels = tops.symbols();
  }
  s.points = chaos.points;
  s.rounds = chaos.rounds;
  s.filled = options.exact ? 0 : chaos.filled;
  s.propagated = options.exact ? 0 : chaos.propagated;
  s.hit = options.exact ? 0 : static_cast<double>(chaos.hit) / static_cast<double>(size.area());
  s.coverage = cv::countNonZero(map.coverage) / static_cast<double>(size.area());
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = s;
  return map;
}

}  // namespace ifsfx
