// SPDX-License-Identifier: Apache-2.0
// compute_steal_map: T(x) = π_G(τ_F(x)) per output pixel (paper §4, docs/design.md §3), by the
// chaos game (tops with address keys, then G applied to each pixel's winning address) or exactly
// (the per-pixel descent).
#include "ifs/steal_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>

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

cv::Mat uv_from_keys(const AddressRaster& tops, const Ifs& F, const Ifs& G, int threads) {
  // The pixel's winning point x is the one with the largest address in the pixel, so it sits at
  // an extreme of the pixel (towards the higher maps' side): evaluating T at x itself would
  // shift the whole picture by up to a pixel. Instead the address is cut after the first m
  // symbols w = σ1 … σm, where the piece f_w(A) holding x has shrunk to about the pixel, and T at
  // the pixel centre x_c is taken from T(x) = g_w(T(f_w⁻¹(x))) on that piece, with T inside
  // approximated by Φ, the affine map of F's attractor box onto G's:
  // T(x_c) ≈ g_w(Φ(f_w⁻¹(x_c))). The error is a fraction of the piece g_w(R), about a pixel, but
  // without the bias of the winning point; it vanishes when Φ = T (F = G: the identity oracle,
  // whatever the pixel grid). Where w holds a singular map (no f_w⁻¹), the centre of g_w(R) is
  // used instead.
  const int k_symbols = tops.symbols();
  const std::uint32_t n = static_cast<std::uint32_t>(G.size());
  const Box fb = attractor_bounds(F);
  const double extent = std::max(fb.width(), fb.height());
  const double pixel = std::min(tops.viewport.view.width() / tops.viewport.size.width,
                                tops.viewport.view.height() / tops.viewport.size.height);
  // Per-map shrink factors of F (maps of factor ≥ 1 that contract in pairs count at F's word rate).
  const double word = word_contraction(F);
  std::vector<double> factor(F.size());
  std::vector<bool> singular(F.size());
  for (std::size_t i = 0; i < F.size(); ++i) {
    const double s = F.maps[i].contraction();
    factor[i] = s < 1 ? s : std::min(word, 0.999);
    singular[i] = !F.maps[i].inverse().has_value();
  }
  const Box gb = attractor_bounds(G);
  const Point centre{0.5 * (gb.x0 + gb.x1), 0.5 * (gb.y0 + gb.y1)};
  // Φ: F's box onto G's, a degenerate side (a line attractor) onto the middle of G's.
  const auto scale = [](double from, double to) { return from > 0 ? to / from : 0.0; };
  const double phi_x = scale(fb.width(), gb.width()), phi_y = scale(fb.height(), gb.height());
  const AffineMap phi{phi_x,
                      0,
                      0,
                      phi_y,
                      centre.x - phi_x * 0.5 * (fb.x0 + fb.x1),
                      centre.y - phi_y * 0.5 * (fb.y0 + fb.y1)};
  cv::Mat uv(tops.viewport.size, CV_32FC2, cv::Scalar::all(0));
  const std::size_t rows = static_cast<std::size_t>(uv.rows);
  parallel_for(rows, threads, [&](std::size_t r, int) {
    auto* out = uv.ptr<cv::Vec2f>(static_cast<int>(r));
    for (int col = 0; col < uv.cols; ++col) {
      const std::uint64_t key = tops.at(col, static_cast<int>(r));
      if (key == 0) continue;
      AffineMap f_w, g_w;  // identities, then f_σ1 ∘ … ∘ f_σm and g_σ1 ∘ … ∘ g_σm
      bool invertible = true;
      double size = extent;
      for (int m = 0; m < k_symbols && size > 1.01 * pixel; ++m) {
        const std::uint32_t sigma = std::min(tops.symbol(key, m), n - 1);
        size *= factor[sigma];
        invertible = invertible && !singular[sigma];
        f_w = f_w.compose(F.maps[sigma]);
        g_w = g_w.compose(G.maps[sigma]);
      }
      std::optional<AffineMap> f_inv;
      if (invertible) f_inv = f_w.inverse(0);
      const Point y = f_inv
                          ? g_w(phi((*f_inv)(tops.viewport.pixel_centre(col, static_cast<int>(r)))))
                          : g_w(centre);
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
