// SPDX-License-Identifier: Apache-2.0
// Colouring IFSs: the default tilings of the unit square (docs/design.md §3: a good default G tiles
// the source rectangle R with N pieces so that every source pixel is reachable), and fitting an
// arbitrary G onto the unit square.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/steal_map.h"

namespace ifsfx {

namespace {

// N strips by "swap" maps g_k(x, y) = (y, (x + k)/N): each has factor 1, two in a row contract by
// 1/N, and together they tile the unit square (g_k maps it onto the strip k/N ≤ y ≤ (k+1)/N).
Ifs swap_strips(std::size_t n) {
  Ifs g;
  g.name = fmt::format("strip-tiling-{}", n);
  const double inv = 1.0 / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k)
    g.maps.push_back({0, 1, inv, 0, 0, static_cast<double>(k) * inv});
  return g;
}

// A cols × rows grid, tiles in raster order from the bottom-left (y up).
Ifs grid(std::size_t cols, std::size_t rows) {
  Ifs g;
  g.name = cols == rows ? fmt::format("square-tiling-{}", cols * rows)
                        : fmt::format("grid-tiling-{}x{}", cols, rows);
  const double sx = 1.0 / static_cast<double>(cols), sy = 1.0 / static_cast<double>(rows);
  for (std::size_t j = 0; j < rows; ++j)
    for (std::size_t i = 0; i < cols; ++i)
      g.maps.push_back({sx, 0, 0, sy, static_cast<double>(i) * sx, static_cast<double>(j) * sy});
  return g;
}

}  // namespace

Ifs default_colouring(std::size_t n) {
  if (n == 0) throw Error(ErrorKind::invalid_ifs, "colouring IFS: needs at least one map (got 0)");
  if (n == 1) {
    // One map cannot tile; the source's centre quarter, so that T stays inside the image.
    Ifs g;
    g.name = "centre-1";
    g.maps.push_back({0.5, 0, 0, 0.5, 0.25, 0.25});
    return g;
  }
  // The most square grid rows × cols = N with rows ≥ 2, else strips (N prime).
  std::size_t rows = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
  while (rows > 1 && n % rows != 0) --rows;
  if (rows < 2) return swap_strips(n);
  return grid(n / rows, rows);
}

Ifs fit_to_unit_square(const Ifs& g) {
  if (g.maps.empty())
    throw Error(ErrorKind::invalid_ifs, "colouring IFS: needs at least one map (got 0)");
  const Box b = attractor_bounds(g);
  // A degenerate side (a line attractor) is centred on the square instead of stretched.
  const double extent = std::max(b.width(), b.height());
  if (!(extent > 0) || !std::isfinite(extent))
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}: the attractor of a colouring IFS must not be a point", g.name));
  const double w = b.width() > 1e-9 * extent ? b.width() : extent;
  const double h = b.height() > 1e-9 * extent ? b.height() : extent;
  const double cx = 0.5 * (b.x0 + b.x1), cy = 0.5 * (b.y0 + b.y1);
  const AffineMap l = rectangle_map(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2, 0, 0, 1, 1);
  const AffineMap l_inv = *l.inverse(0);
  Ifs out = g;
  for (auto& m : out.maps) m = l.compose(m).compose(l_inv);  // L ∘ g_n ∘ L⁻¹
  return out;
}

}  // namespace ifsfx
