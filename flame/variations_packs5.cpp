// SPDX-License-Identifier: Apache-2.0
// The last variations of Fractorium's example packs that a 2-D registry function draws as the
// packs' renderers do: nBlur (FractalDesire's n-gon blur), depth_blur2 (a star-shaped blur that
// grows beyond a radius: 2-D despite its name) and dc_ztransl (linear in x and y; what it
// changes is z), each from the formula as docs/flames.md states it.
#include <algorithm>
#include <cmath>
#include <utility>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

// nBlur draws a point of a regular polygon of n corners (at distance 1, before the weight) and
// reads no point. Its angles are measured from the y axis, clockwise, in sectors of α = 2π/n
// from one corner to the next; the drawn point is turned anticlockwise by α/2 at the end.
constexpr VariationParameter kNBlur[] = {
    {"nBlur_numEdges", 3},  {"nBlur_numStripes", 0},   {"nBlur_ratioStripes", 1},
    {"nBlur_ratioHole", 0}, {"nBlur_circumCircle", 0}, {"nBlur_adjustToLinear", 1},
    {"nBlur_equalBlur", 1}, {"nBlur_exactCalc", 0},    {"nBlur_highlightEdges", 1}};

// The polygon, its stripes and its hole, fixed by the parameters.
struct NGon {
  double n = 3;          // corners, ≥ 3
  double alpha = 0;      // 2π/n
  double bands = 0;      // 2·|numStripes|: the sector's bands, 0 without stripes
  double band = 0;       // α/bands, one band's angle
  int lit_parity = 0;    // the bands centred at even (0) or odd (1) multiples of `band` are lit
  double lit_width = 1;  // a lit band's width, in bands
  double hole = 0;       // the empty polygon's size, a fraction of the outer one
  bool circum = false, equal = false, exact = false;
  double gain = 1;  // how strongly the angles crowd towards the spokes
  double w = 1;     // the weight, divided by sin(mπ/n) with adjustToLinear
};

// A switch (0 or 1, a value beyond taken as the nearer); the plugin's whole-number parameters
// are rounded as every mode parameter (mode_of).
bool on(double v) {
  return mode_of(v) >= 1;
}

NGon ngon_of(std::span<const double> k, double w) {
  NGon g;
  g.n = std::max(mode_of(k[0]), 3);
  g.alpha = 2 * kPi / g.n;
  const double stripes = mode_of(k[1]);
  const double ratio = std::isnan(k[2]) ? 1 : std::clamp(k[2], 0.0, 2.0);
  g.bands = 2 * std::abs(stripes);
  g.band = stripes == 0 ? 0 : g.alpha / g.bands;
  g.lit_parity = stripes < 0 ? 1 : 0;
  g.lit_width = stripes < 0 ? 2 - ratio : ratio;
  g.circum = on(k[4]);
  g.equal = on(k[6]);
  g.exact = on(k[7]) && !g.circum;
  g.hole = std::isnan(k[3]) ? 0 : std::clamp(k[3], 0.0, g.exact ? 0.95 : 1.0);
  const double highlight = g.circum || !(k[8] > 0.1) ? 0.1 : k[8];
  g.gain = (stripes < 0 ? 7.5 : 13) / std::pow(g.n, 1.3) * highlight;
  // sin(mπ/n) is half the chord between corners m apart: the polygon's half width
  const double m = std::fmod(g.n, 4) == 0 ? g.n / 2 - 1 : std::floor(g.n / 2);
  g.w = on(k[5]) ? w / std::sin(m * kPi / g.n) : w;
  return g;
}

// The angle a ∈ [0, α] within a sector, and the sector's first corner k·α. Exact: uniform over
// the turn (one draw). Else t = ½ − atan(g·(u − ½))/(2·atan(g/2)) ∈ [0, 1], u the first draw,
// which crowds the angles towards the sector's ends, and the sector k = ⌊nΨ⌋, the second.
std::pair<double, double> ngon_angle(const NGon& g, Rng& rng) {
  if (g.exact) {
    const double t = 2 * kPi * psi(rng), k = std::floor(t / g.alpha);
    return {std::clamp(t - k * g.alpha, 0.0, g.alpha), k * g.alpha};
  }
  const double u = psi(rng);
  const double t = 0.5 - std::atan(g.gain * (u - 0.5)) / (2 * std::atan(g.gain / 2));
  return {t * g.alpha, std::floor(psi(rng) * g.n) * g.alpha};
}

// The stripes: the sector is cut into bands of width b centred at the multiples c·b, c = 0 …
// bands (the end ones halves, completed by the next sector). A point in a band of the unlit
// parity moves half a band away from its centre, into the neighbour; then the lit band is
// scaled about its centre to lit_width·b: stretched when wider than b, its outer parts folded
// in (|d| − h)·h/(b/2 − h), h = lit_width·b/2, when narrower.
double ngon_stripes(const NGon& g, double a) {
  const double b = g.band;
  double c = std::clamp(std::ceil(a / b - 0.5), 0.0, g.bands);
  double d = a - c * b;
  if (std::fmod(c, 2) != g.lit_parity) {
    const bool up = d > 0 || c == 0;
    c += up ? 1 : -1;
    d += up ? -b / 2 : b / 2;
  }
  const double h = g.lit_width * b / 2;
  if (g.lit_width > 1)
    d *= g.lit_width;
  else if (std::abs(d) > h)
    d = std::copysign((std::abs(d) - h) * h / (b / 2 - h), d);
  return c * b + d;
}

// One try: the angle A from the y axis, the radius ρ and the polygon's radius R on that ray,
// R = cos(α/2)/cos(a − α/2) (the corners at 1). The radius draw u: √u with equalBlur (uniform
// over the area), else u. Exact: ρ = u, kept or not by the caller. Else ρ = u·R (u with
// circumCircle: the circumscribed disc), and a ρ inside the hole, below hole·R, is drawn again
// between hole·R and the outer bound (R, or 1 with circumCircle) with a third draw.
struct NGonTry {
  double angle, rho, edge;
};
NGonTry ngon_try(const NGon& g, Rng& rng) {
  auto [a, first] = ngon_angle(g, rng);
  if (g.band > 0) a = ngon_stripes(g, a);
  const double edge = std::cos(g.alpha / 2) / std::cos(a - g.alpha / 2), inner = g.hole * edge;
  const auto draw = [&] {
    const double u = psi(rng);
    return g.equal ? std::sqrt(u) : u;
  };
  double rho = draw();
  if (g.exact) return {first + a, rho, edge};
  const double outer = g.circum ? 1 : edge;
  if (!g.circum) rho *= edge;
  if (rho < inner) rho = inner + draw() * (outer - inner);
  return {first + a, rho, edge};
}

// Exact: whole tries again until hole·R ≤ ρ ≤ R. A try is kept with odds of 4% or more (a
// triangle, hole 0.95); the bound only keeps the loop finite whatever a generator gives.
Point n_blur(const VariationInput& in, Rng& rng) {
  const NGon g = ngon_of(in.params, in.w);
  NGonTry t = ngon_try(g, rng);
  for (int k = 0; g.exact && k < 1000 && !(t.rho >= g.hole * t.edge && t.rho <= t.edge); ++k)
    t = ngon_try(g, rng);
  // (ρ sin A, ρ cos A) turned anticlockwise by α/2: the angle π/2 + α/2 − A from the x axis
  const double beta = kPi / 2 + g.alpha / 2 - t.angle;
  return scaled(g.w * t.rho, std::cos(beta), std::sin(beta));
}

// depth_blur2: beyond `radius` of the ellipse distance ρ = |((x − x0)/mulx, (y − y0)/muly)|, p
// moves by a random point of a star of P = `power` points, its tips at 1 and its inner corners
// at `range`, scaled by blur/10·(ρ − radius)^exp. The star's edge from a tip to an inner corner
// has length L = √(1 + range² − 2·range·cos(π/P)) and meets the tip's ray at γ = asin(sin(π/P)·
// range/L). The first draw f = 2PΨ picks the edge j = trunc f and the distance x = (f − j)·L
// from its tip, at z = √(1 + x² − 2x·cos γ) from the centre and δ = asin(sin γ·x/z) from the
// tip's ray: the angle θ = (2π/P)·⌊j/2⌋ ± δ (+ for odd j); the second draw moves it inwards,
// z·√Ψ. The offset is z·s·(cos(θ − π/2), sin(θ − π/2)); then w·(p + offset).
constexpr VariationParameter kDepthBlur2[] = {
    {"depth_blur2_power", 5},  {"depth_blur2_range", 0.401623}, {"depth_blur2_blur", 1},
    {"depth_blur2_radius", 1}, {"depth_blur2_x0", 0},           {"depth_blur2_y0", 0},
    {"depth_blur2_mulx", 1},   {"depth_blur2_muly", 1},         {"depth_blur2_exp", 1}};
double nonzero(double v) {
  return v == 0 ? kEps : v;
}
Point depth_blur2(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const auto [x, y] = in.p;
  const double rho = std::hypot((x - k[4]) / nonzero(k[6]), (y - k[5]) / nonzero(k[7]));
  if (!(rho > k[3])) return scaled(in.w, x, y);
  const double half = kPi / nonzero(k[0]);
  const double len = std::sqrt(1 + k[1] * k[1] - 2 * k[1] * std::cos(half));
  const double gamma = std::asin(std::clamp(std::sin(half) * k[1] / nonzero(len), -1.0, 1.0));
  double f = psi(rng) * 2 * k[0];
  const double j = std::trunc(f);
  f -= j;
  const double along = f * len;
  double z = std::sqrt(1 + along * along - 2 * along * std::cos(gamma));
  const double delta = std::asin(std::clamp(std::sin(gamma) * along / nonzero(z), -1.0, 1.0));
  const double theta = 2 * half * std::trunc(j / 2) + (std::fmod(j, 2) != 0 ? delta : -delta);
  z *= std::sqrt(psi(rng));
  const double s = z * k[2] / 10 * std::pow(rho - k[3], k[8]);
  return scaled(in.w, x + s * std::sin(theta), y - s * std::cos(theta));
}

// dc_ztransl: w·(x, y); its z (from the colour coordinate) is what it changes, and a 2-D
// point has none. Its parameters are read and written back.
constexpr VariationParameter kDcZtransl[] = {{"dc_ztransl_x0", 0},
                                             {"dc_ztransl_x1", 1},
                                             {"dc_ztransl_factor", 1},
                                             {"dc_ztransl_overwrite", 1},
                                             {"dc_ztransl_clamp", 0}};
Point dc_ztransl(const VariationInput& in, Rng&) {
  return scaled(in.w, in.p.x, in.p.y);
}

}  // namespace

void add_pack5_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "nBlur", .parameters = kNBlur, .function = n_blur, .kind = K::random},
      {.name = "depth_blur2",
       .parameters = kDepthBlur2,
       .function = depth_blur2,
       .kind = K::random},
      {.name = "dc_ztransl", .parameters = kDcZtransl, .function = dc_ztransl},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
