// SPDX-License-Identifier: Apache-2.0
// The second pass of variations beyond flam3's by their count in Fractorium's example packs
// (docs/flames.md): slobo777's Voronoi cells crackle and hexes, zy0rg's smartcrop, each from the
// formula as docs/flames.md states it (what each parameter means, the order of the random draws,
// the conventions chosen).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "flame/detail/simplex_noise.h"
#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

// Where u lies in the Voronoi cell of centre c against its neighbours n: the largest of
// 2(u − c)·(n − c)/|n − c|² over them. It is 0 at c and 1 on the cell's edge (the bisector of c
// and the nearest n), so that the cell is the set where it is ≤ 1: a polygonal "radius".
template <std::size_t N>
double cell_level(const std::array<Point, N>& n, std::size_t c, Point u) {
  double level = std::numeric_limits<double>::lowest();
  for (std::size_t i = 0; i < N; ++i) {
    if (i == c) continue;
    const double dx = n[i].x - n[c].x, dy = n[i].y - n[c].y, d2 = dx * dx + dy * dy;
    const double ratio = d2 == 0 ? 1.0 : 2 * ((u.x - n[c].x) * dx + (u.y - n[c].y) * dy) / d2;
    level = std::max(level, ratio);
  }
  return level;
}

// The index of the point of `p` nearest to u (the first of equals).
template <std::size_t N>
std::size_t nearest(const std::array<Point, N>& p, Point u) {
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < N; ++i) {
    const double d2 = (p[i].x - u.x) * (p[i].x - u.x) + (p[i].y - u.y) * (p[i].y - u.y);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  return best;
}

// crackle's cell centres: lattice point (i, j) at spacing s, each coordinate moved by
// `distort` times a simplex noise sampled 2.5 lattice units apart (nearly independent from one
// cell to the next), x's and y's noise read at places far apart in the noise's space, `z` the
// slice of it.
struct CrackleCells {
  double s, distort, z;

  Point centre(double i, double j) const {
    if (distort == 0) return {i * s, j * s};
    const double a = 2.5 * i, b = 2.5 * j, c = 2.5 * z;
    return {(i + distort * simplex_noise(a, b, c)) * s,
            (j + distort * simplex_noise(b + 30.2, a - 12.1, c + 19.8)) * s};
  }
  // The 3×3 centres about cell (i, j), j fastest: index 4 is (i, j), index q is
  // (i + q/3 − 1, j + q%3 − 1).
  std::array<Point, 9> block(double i, double j) const {
    std::array<Point, 9> p{};
    for (std::size_t q = 0; q < 9; ++q)
      p[q] = centre(i + static_cast<double>(q / 3) - 1, j + static_cast<double>(q % 3) - 1);
    return p;
  }
  // The block about (i, j), the middle of `old` (the block about (i − di, j − dj)) moved by
  // (di, dj): the centres the two share are taken from `old` (the noise is the cost).
  std::array<Point, 9> moved(const std::array<Point, 9>& old, double i, double j, int di,
                             int dj) const {
    std::array<Point, 9> p{};
    for (int q = 0; q < 9; ++q) {
      const int a = q / 3 + di, b = q % 3 + dj;
      p[static_cast<std::size_t>(q)] =
          a >= 0 && a <= 2 && b >= 0 && b <= 2
              ? old[static_cast<std::size_t>(a * 3 + b)]
              : centre(i + static_cast<double>(q / 3 - 1), j + static_cast<double>(q % 3 - 1));
    }
    return p;
  }
};

// crackle: a random point u of a blurred unit circle, b·(sin θ, cos θ), b = (Ψ1 + Ψ2)/2 +
// (Ψ3 − ½)/4, θ = 2πΨ4 (the draws in that order; the affine point is not read), moved within
// its Voronoi cell of centre c: w·(c + (u − c)·scale·L^power/L), L = cell_level (power 0 and
// scale 1 push every point onto its cell's edge; scale 0 leaves the centres only).
constexpr VariationParameter kCrackle[] = {{"crackle_cellsize", 1},
                                           {"crackle_power", 0.2},
                                           {"crackle_distort", 0},
                                           {"crackle_scale", 1},
                                           {"crackle_z", 0}};
Point crackle(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  if (k[0] == 0) return {0, 0};
  const double u1 = psi(rng), u2 = psi(rng), u3 = psi(rng), u4 = psi(rng);
  const double b = (u1 + u2) / 2 + (u3 - 0.5) / 4, theta = 2 * kPi * u4;
  const Point u{b * std::sin(theta), b * std::cos(theta)};
  const CrackleCells cells{std::abs(k[0]) / 2, k[2], k[4]};
  double i = std::floor(u.x / cells.s), j = std::floor(u.y / cells.s);
  std::array<Point, 9> p = cells.block(i, j);
  // The nearest of the nine need not be the middle one: the block is made again about it so
  // that its cell is surrounded.
  if (const std::size_t q = nearest(p, u); q != 4) {
    const int di = static_cast<int>(q / 3) - 1, dj = static_cast<int>(q % 3) - 1;
    i += di;
    j += dj;
    p = cells.moved(p, i, j, di, dj);
  }
  double level = cell_level(p, 4, u);
  if (level == 0) level = kEps;
  const double r = std::pow(std::abs(level), k[1]) * k[3] / level;
  return scaled(in.w, p[4].x + (u.x - p[4].x) * r, p[4].y + (u.y - p[4].y) * r);
}

// hexes: the plane cut into hexagons of centres s·(3/2·(a − b), √3/2·(a + b)) for whole a, b;
// in its cell of centre c, p's offset d = p − c is turned clockwise by 2π·rotate and scaled so
// that its cell level becomes scale·L1^power: by scale·L1^power/L1 where the level L = max(L1,
// L2) of p and of the turned point is below ½, by scale·L1^power/L2 above 0.8, and by the
// linear blend of the two between (the plugin's cure for the rosettes the corners make).
constexpr VariationParameter kHexes[] = {
    {"hexes_cellsize", 1}, {"hexes_power", 1}, {"hexes_rotate", 0.166}, {"hexes_scale", 1}};
Point hexes(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const double s = k[0];
  if (s == 0) return {0, 0};
  const double r3 = std::sqrt(3.0);
  const auto centre = [&](double a, double b) {
    return Point{1.5 * (a - b) * s, r3 / 2 * (a + b) * s};
  };
  const Point u = in.p;
  double a = std::floor((u.x + r3 * u.y) / 3 / s), b = std::floor((-u.x + r3 * u.y) / 3 / s);
  std::array<Point, 9> block{};
  for (std::size_t q = 0; q < 9; ++q)
    block[q] = centre(a + static_cast<double>(q / 3) - 1, b + static_cast<double>(q % 3) - 1);
  const std::size_t q = nearest(block, u);
  a += static_cast<double>(q / 3) - 1;
  b += static_cast<double>(q % 3) - 1;
  const std::array<Point, 7> hex{centre(a, b),     centre(a, b + 1), centre(a + 1, b + 1),
                                 centre(a + 1, b), centre(a, b - 1), centre(a - 1, b - 1),
                                 centre(a - 1, b)};
  const Point c = hex[0];
  double l1 = cell_level(hex, 0, u);
  if (l1 == 0) l1 = kEps;
  const double target = std::pow(l1, k[1]) * k[3];
  const double sn = std::sin(2 * kPi * k[2]), cs = std::cos(2 * kPi * k[2]);
  const double dx = u.x - c.x, dy = u.y - c.y;
  const double vx = dx * cs + dy * sn, vy = -dx * sn + dy * cs;
  double l2 = cell_level(hex, 0, {c.x + vx, c.y + vy});
  if (l2 == 0) l2 = kEps;
  const double l = std::max(l1, l2);
  const double r = l < 0.5   ? target / l1
                   : l > 0.8 ? target / l2
                             : (target / l1 * (0.8 - l) + target / l2 * (l - 0.5)) / 0.3;
  return scaled(in.w, c.x + vx * r, c.y + vy * r);
}

// smartcrop's parameters, in the registry's order.
struct SmartcropParams {
  double power, radius, roundstr, roundwidth, distortion, edge, scatter, offset, rotation;
  int cropmode;

  explicit SmartcropParams(std::span<const double> k)
      : power(k[0]),
        radius(k[1]),
        roundstr(k[2]),
        roundwidth(k[3]),
        distortion(k[4]),
        edge(k[5]),
        scatter(k[6]),
        offset(k[7]),
        rotation(k[8]),
        cropmode(mode_of(k[9])) {}
  // Which side is cut: the outside when power and radius have the same sign, else the inside.
  bool cut_outside() const { return (power > 0) == (radius > 0); }
};

// A cut point with crop mode 2 ("scatter among the uncropped points"): the plugin puts it on
// the last point it kept, a state this registry's functions do not hold; a point that is not a
// number, which the walker drops and starts again (docs/flames.md).
constexpr double kDropped = std::numeric_limits<double>::quiet_NaN();

// |power| < 2: a sector. With e = edge·(Ψ − ½) (always drawn), the angle a = frac(φ/2π + 1 +
// e)·2π is cut when (a > |power|·π) matches cut_outside(); a cut point keeps its radius and
// goes to one of the sector's edges (Ψ < ½: the start, angle −(Ψ'·scatter + offset + e)·π;
// else the end, |power|·π + (Ψ'·scatter + offset + e)·π).
Point smartcrop_sector(const SmartcropParams& k, const VariationInput& in, Rng& rng) {
  const auto [x, y] = in.p;
  const double phi = std::atan2(y, x), r = std::hypot(x, y), span = std::abs(k.power) * kPi;
  const double e = k.edge * (psi(rng) - 0.5);
  const double turn = phi / (2 * kPi) + 1 + e, a = (turn - std::trunc(turn)) * 2 * kPi;
  if ((a > span) != k.cut_outside()) return scaled(in.w, x, y);
  if (k.cropmode == 2) return {kDropped, kDropped};
  const bool end = psi(rng) >= 0.5;
  const double move = (psi(rng) * k.scatter + k.offset + e) * kPi;
  const double to = end ? span + move : -move;
  return scaled(in.w * r, std::cos(to), std::sin(to));
}

// zy0rg's regular polygon of n sides (α = 2π/n), as a multiple of its apothem: the border's
// radius at the angle t·α from the middle of a side (t ∈ [0, ½]) is 1/cos(t·α), bent by the
// rounding (roundstr ≠ 0: m = (2t)^roundwidth · 2·roundstr/(n·sin(α/2)), coeff ← |(1 − m)·coeff
// + m|: the corners rounded, dimpled for larger roundstr) and raised to `distortion` (0: a
// circle). smartcrop and smartshape share it.
double polygon_border(double t, double n, double roundstr, double roundwidth, double distortion) {
  if (distortion == 0) return 1;
  const double alpha = 2 * kPi / n;
  double coeff = 1 / std::cos(t * alpha);
  if (roundstr != 0) {
    double round_coeff = std::sin(alpha / 2);
    if (round_coeff == 0) round_coeff = kEps;
    round_coeff = roundstr / round_coeff / n * 2;
    const double width = (roundwidth != 1 ? std::pow(2 * t, roundwidth) : 2 * t) * round_coeff;
    coeff = std::abs((1 - width) * coeff + width);
  }
  return distortion != 1 ? std::pow(coeff, distortion) : coeff;
}

// |power| ≥ 2: the polygon of n = |power| sides, apothem |radius|, the middles of its sides at
// angles −π + k·α (α = 2π/n): the border's radius at angle φ is |radius|·coeff, coeff =
// polygon_border(t), t the distance of (φ + π)/α from the nearest whole number. `edge` jitters
// that radius by edge·(Ψ − ½) (drawn only when edge ≠ 0). A cut point goes to the origin (crop
// mode 0), keeps its radius (−1), or goes onto the border moved out by coeff·(Ψ·scatter +
// offset) (1), its angle turned by rotation·α.
Point smartcrop_polygon(const SmartcropParams& k, const VariationInput& in, Rng& rng) {
  const auto [x, y] = in.p;
  const double phi = std::atan2(y, x), r = std::hypot(x, y), n = std::abs(k.power);
  const double alpha = 2 * kPi / n;
  double t = (phi + kPi) / alpha;
  t -= std::trunc(t);
  const double coeff =
      polygon_border(std::min(t, 1 - t), n, k.roundstr, k.roundwidth, k.distortion);
  const double radius = std::abs(k.radius) + (k.edge != 0 ? k.edge * (psi(rng) - 0.5) : 0.0);
  const double border = coeff * radius;
  if ((r > border) != k.cut_outside()) return scaled(in.w, x, y);
  if (k.cropmode == 2) return {kDropped, kDropped};
  if (k.cropmode == 0) return {0, 0};
  const double to_r = k.cropmode == -1 ? r : border + coeff * (psi(rng) * k.scatter + k.offset);
  const double to = phi + k.rotation * alpha;
  return scaled(in.w * to_r, std::cos(to), std::sin(to));
}

// smartcrop (zy0rg's Apophysis plugin, post_smartcrop in the packs): w·p inside the shape, the
// cut points moved as the two functions above say. `static` is read and written back; every
// value acts as 2, the one the packs use (docs/flames.md).
constexpr VariationParameter kSmartcrop[] = {
    {"smartcrop_power", 4},      {"smartcrop_radius", 1},     {"smartcrop_roundstr", 0},
    {"smartcrop_roundwidth", 1}, {"smartcrop_distortion", 1}, {"smartcrop_edge", 0},
    {"smartcrop_scatter", 0},    {"smartcrop_offset", 0},     {"smartcrop_rotation", 0},
    {"smartcrop_cropmode", 1},   {"smartcrop_static", 1}};
Point smartcrop(const VariationInput& in, Rng& rng) {
  const SmartcropParams k(in.params);
  return std::abs(k.power) < 2 ? smartcrop_sector(k, in, rng) : smartcrop_polygon(k, in, rng);
}

// smartshape: the plane stretched radially so that circles about the origin become zy0rg's
// polygon (n = max(power, 2) sides, apothem r): w·r·coeff at the angle φ, coeff = polygon_border
// at φ's distance t from the nearest side's middle. With `compensation` > 0 (and distortion ≥ 1)
// the angle is first remapped, t ← atan(2·tan(α/2)·t)/α, so that the points spread evenly along
// each side.
constexpr VariationParameter kSmartshape[] = {{"smartshape_power", 4},
                                              {"smartshape_roundstr", 0},
                                              {"smartshape_roundwidth", 1},
                                              {"smartshape_distortion", 1},
                                              {"smartshape_compensation", 0}};
Point smartshape(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const double n = std::max(k[0], 2.0), alpha = 2 * kPi / n;
  const double turns = (polar(in).phi() + kPi) / alpha, whole = std::floor(turns);
  const double f = turns - whole;
  const bool upper = f > 0.5;
  double t = upper ? 1 - f : f;
  if (k[4] > 0 && k[3] >= 1) t = std::atan(t * 2 * std::tan(alpha / 2)) / alpha;
  const double coeff = polygon_border(t, n, k[1], k[2], k[3]);
  const double a = (upper ? whole + 1 - t : whole + t) * alpha - kPi;
  return scaled(in.w * coeff * polar(in).r(), std::cos(a), std::sin(a));
}

}  // namespace

void add_pack2_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "crackle", .parameters = kCrackle, .function = crackle, .kind = K::random},
      {.name = "hexes", .parameters = kHexes, .function = hexes},
      {.name = "smartcrop", .parameters = kSmartcrop, .function = smartcrop, .kind = K::random},
      {.name = "smartshape", .parameters = kSmartshape, .function = smartshape},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
