// SPDX-License-Identifier: Apache-2.0
// The next variations beyond flam3's set by their count in Fractorium's example packs
// (docs/flames.md): the Apophysis 7X plugins falloff2, bwraps, unpolar, glynnia, tile_log,
// tile_hlp, curl3D's z = 0 slice, twoface, hypertile2, Ember's gaussian, bTransform and crop, each
// from the formula as docs/flames.md states it (what each parameter means, the order of the random
// draws, the conventions chosen).
#include <algorithm>
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

// falloff2: the point blurred by an amount that grows with its distance from (x0, y0, z0)
// beyond `mindist`: dist = max((d − mindist)·0.04·scatter, 0), d = |p − p0| (or max(1 − |p −
// p0|, 0) with `invert`); `type` 0 moves x and y by uniform offsets, 1 the radius and the
// angle, 2 by a random direction. The four draws u ∈ [−½, ½) are taken in the order x, y, z,
// colour (the plugin's); `mul_c`, the colour's offset, is read and written but not applied.
constexpr VariationParameter kFalloff2[] = {
    {"falloff2_scatter", 1}, {"falloff2_mindist", 0.5}, {"falloff2_mul_x", 1},
    {"falloff2_mul_y", 1},   {"falloff2_mul_z", 0},     {"falloff2_mul_c", 0},
    {"falloff2_x0", 0},      {"falloff2_y0", 0},        {"falloff2_z0", 0},
    {"falloff2_invert", 0},  {"falloff2_type", 0}};
Point falloff2(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double ux = psi(rng) - 0.5, uy = psi(rng) - 0.5, uz = psi(rng) - 0.5;
  (void)psi(rng);  // the colour's draw: taken so that the stream stays the plugin's
  const auto [x, y] = in.p;
  const double d = std::sqrt((x - k[6]) * (x - k[6]) + (y - k[7]) * (y - k[7]) + k[8] * k[8]);
  const double db = k[9] != 0 ? std::max(1 - d, 0.0) : d;
  const double dist = std::max((db - k[1]) * 0.04 * k[0], 0.0);
  const int type = mode_of(k[10]);
  if (type == 0) return scaled(in.w, x + k[2] * ux * dist, y + k[3] * uy * dist);
  if (type == 1) {
    if (x == 0 && y == 0) return {0, 0};
    const double r = std::hypot(x, y) + k[2] * ux * dist;
    const double phi = std::atan2(y, x) + k[3] * uy * dist, sigma = k[4] * uz * dist;
    return scaled(in.w * r * std::cos(sigma), std::cos(phi), std::sin(phi));
  }
  const double sigma = dist * uy * 2 * kPi, phi = dist * uz * kPi, rad = dist * ux;
  return scaled(in.w, x + k[2] * rad * std::cos(sigma) * std::cos(phi),
                y + k[3] * rad * std::cos(sigma) * std::sin(phi));
}

// bwraps ("bubble wrap"): the plane cut into cells of side `cellsize`; in the disc of radius
// R = cellsize/2/(1 + space²) about each cell's centre c the offset l = p − c is magnified as
// a bubble, l ← f·g²·l/(g⁴|l|²/4 + 1) (g² = gain² + 10⁻⁶, f scaling the disc's rim back onto
// itself), and turned by θ = inner·(1 − t) + outer·t, t = |l|²/R²; outside the discs p stays.
constexpr VariationParameter kBwraps[] = {{"bwraps_cellsize", 1},
                                          {"bwraps_space", 0},
                                          {"bwraps_gain", 1},
                                          {"bwraps_inner_twist", 0},
                                          {"bwraps_outer_twist", 0}};
Point bwraps(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const double cell = k[0], radius = 0.5 * cell / (1 + k[1] * k[1]);
  if (cell == 0) return scaled(in.w, in.p.x, in.p.y);
  const double g2 = k[2] * k[2] + 1e-6, bubble = g2 * radius;
  const double max_bubble = bubble > 2 ? 1 : bubble / (bubble * bubble / 4 + 1);
  const double r2 = radius * radius == 0 ? kEps : radius * radius;
  const double cx = (std::floor(in.p.x / cell) + 0.5) * cell;
  const double cy = (std::floor(in.p.y / cell) + 0.5) * cell;
  double lx = in.p.x - cx, ly = in.p.y - cy;
  if (lx * lx + ly * ly > r2) return scaled(in.w, in.p.x, in.p.y);
  lx *= g2;
  ly *= g2;
  const double f = radius / max_bubble / ((lx * lx + ly * ly) / 4 + 1);
  lx *= f;
  ly *= f;
  const double t = (lx * lx + ly * ly) / r2, theta = k[3] * (1 - t) + k[4] * t;
  const double s = std::sin(theta), c = std::cos(theta);
  return scaled(in.w, cx + c * lx + s * ly, cy - s * lx + c * ly);
}

// unpolar: polar's inverse, w/(2π)·e^y·(sin x, cos x).
Point unpolar(const VariationInput& in, Rng&) {
  const double r = in.w / (2 * kPi) * std::exp(in.p.y);
  return {r * std::sin(in.p.x), r * std::cos(in.p.x)};
}

// glynnia (Apophysis 7X's form, Ember's default): r = |p|, a draw Ψ picks one of two square
// roots of the plane; inside the unit circle x is mirrored.
Point glynnia(const VariationInput& in, Rng& rng) {
  const auto [x, y] = in.p;
  const double r = std::hypot(x, y), v2 = in.w * std::sqrt(2.0) / 2;
  const double mirror = r > 1 ? 1.0 : -1.0;
  if (psi(rng) > 0.5) {
    double d = std::sqrt(r + x);
    if (d == 0) d = kEps;
    return {mirror * v2 * d, -(v2 / d * y)};
  }
  const double d = r + x;
  double q = std::sqrt(r * (y * y + d * d));
  if (q == 0) q = kEps;
  return {mirror * in.w / q * d, in.w / q * y};
}

// tile_log: x moved by a whole number of tiles, round(±spread·ln U), U = 1 − Ψ ∈ (0, 1] (so the
// logarithm is finite), the sign from a second draw: copies of the plane tiled along x with
// weights falling off geometrically.
constexpr VariationParameter kTileLog[] = {{"tile_log_spread", 1}};
Point tile_log(const VariationInput& in, Rng& rng) {
  const double u = 1 - psi(rng), spread = (rng.next() >> 63) ? in.params[0] : -in.params[0];
  const double tile = std::round(std::log(u) * spread);
  return scaled(in.w, in.p.x + tile, in.p.y);
}

// tile_hlp: with t = x/width and f = t − trunc(t), the point moves one tile towards the origin
// (w·width) when cos(π·f) < 2Ψ − 1: never at f = 0, with odds ½ at f = ½.
constexpr VariationParameter kTileHlp[] = {{"tile_hlp_width", 1}};
Point tile_hlp(const VariationInput& in, Rng& rng) {
  const double width = in.params[0], t = in.p.x / width;
  const double f = t - std::trunc(t), shift = in.w * width;
  const double move = std::cos(kPi * f) < 2 * psi(rng) - 1 ? (t > 0 ? -shift : shift) : 0.0;
  return {in.w * in.p.x + move, in.w * in.p.y};
}

// curl3D at z = 0: w·(x + cx·r², y − cy·r²)/(r²·|c|² + 2cx·x − 2cy·y + 1), c = (cx, cy, cz).
constexpr VariationParameter kCurl3D[] = {{"curl3D_cx", 0}, {"curl3D_cy", 0}, {"curl3D_cz", 0}};
Point curl_3d(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const auto [x, y] = in.p;
  const double r2 = x * x + y * y, c2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
  double den = r2 * c2 + 2 * k[0] * x - 2 * k[1] * y + 1;
  if (den == 0) den = kEps;
  const double r = in.w / den;
  return {r * (x + k[0] * r2), r * (y - k[1] * r2)};
}

// twoface: spherical on the half-plane x > 0, linear on the other.
Point twoface(const VariationInput& in, Rng&) {
  const double r2 = polar(in).r2();
  const double k = in.p.x > 0 ? in.w / (r2 == 0 ? kEps : r2) : in.w;
  return {k * in.p.x, k * in.p.y};
}

// hypertile2: a Möbius map of the Poincaré disc, z ↦ (z + R)/(R·z + 1), then a turn by a random
// multiple k of 2π/p (k = ⌊32767·Ψ⌋, as the plugin draws it), R = 1/√(1 − (cos a − 1)/(cos a +
// cos(2π/q))), a = 2π/p (R = 1 when the root's argument is not positive): the {p, q} tiling.
constexpr VariationParameter kHypertile2[] = {{"hypertile2_p", 3}, {"hypertile2_q", 7}};
// hypertile3D2 at z = 0 is hypertile2's map (its 3-D form of the same Möbius map, z = 0).
constexpr VariationParameter kHypertile3D2[] = {{"hypertile3D2_p", 3}, {"hypertile3D2_q", 7}};
Point hypertile2(const VariationInput& in, Rng& rng) {
  const auto [pa, big_r] = hyper_tiling(in.params[0], in.params[1]);
  const auto [x, y] = in.p;
  const double a = x + big_r, b = y, c = big_r * x + 1, d = big_r * y;
  const double u = a * c + b * d, v = b * c - a * d;
  const double den = c * c + d * d, vr = in.w / (den == 0 ? kEps : den);
  const double t = std::floor(32767 * psi(rng)) * pa, sn = std::sin(t), cn = std::cos(t);
  return {vr * (u * cn + v * sn), vr * (v * cn - u * sn)};
}

// gaussian (Ember's): p plus a random offset of radius w·(Ψ1 + Ψ2 + Ψ3 + Ψ4 − 2) in a random
// direction (the direction drawn first); unlike gaussian_blur, the point itself is kept.
Point gaussian(const VariationInput& in, Rng& rng) {
  const double angle = 2 * kPi * psi(rng), r = in.w * sum_of_four(rng);
  return {in.p.x + r * std::cos(angle), in.p.y + r * std::sin(angle)};
}

// bTransform: the point in bipolar coordinates (foci ±1): τ = ln(|z + 1|/|z − 1|), σ = π −
// arg(z + 1) − arg(1 − z); τ/power + move (± split by the sign of x), σ turned by `rotate`,
// divided by `power` and put on a random one of its `power` branches; back to the plane,
// w·(sinh τ, sin σ)/(cosh τ − cos σ). Power 1 and no offsets give the identity.
constexpr VariationParameter kBTransform[] = {{"bTransform_rotate", 0},
                                              {"bTransform_power", 1},
                                              {"bTransform_move", 0},
                                              {"bTransform_split", 0}};
Point b_transform(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const auto [x, y] = in.p;
  const double power = k[1] == 0 ? kEps : k[1];
  const double ln_ratio = std::log((x + 1) * (x + 1) + y * y) - std::log((x - 1) * (x - 1) + y * y);
  double tau = 0.5 * ln_ratio / power + k[2];
  double sigma = kPi - std::atan2(y, x + 1) - std::atan2(y, 1 - x) + k[0];
  sigma = sigma / power + 2 * kPi / power * std::floor(psi(rng) * power);
  tau += x >= 0 ? k[3] : -k[3];
  double den = std::cosh(tau) - std::cos(sigma);
  if (den == 0) den = kEps;
  return {in.w * std::sinh(tau) / den, in.w * std::sin(sigma) / den};
}

// crop: the rectangle [left, right] × [top, bottom] (either order); a point outside it goes to
// the origin with `zero`, else each coordinate outside is put back inside, at the edge moved
// in by Ψ·scatter_area·(half the side) — the x draw first, a draw only for a coordinate outside.
constexpr VariationParameter kCrop[] = {{"crop_scatter_area", 0}, {"crop_left", -1},
                                        {"crop_right", 1},        {"crop_top", -1},
                                        {"crop_bottom", 1},       {"crop_zero", 0}};
Point crop(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double x0 = std::min(k[1], k[2]), x1 = std::max(k[1], k[2]);
  const double y0 = std::min(k[3], k[4]), y1 = std::max(k[3], k[4]);
  auto [x, y] = in.p;
  const bool outside = x < x0 || x > x1 || y < y0 || y > y1;
  if (outside && k[5] != 0) return {0, 0};
  const double w = (x1 - x0) * 0.5 * k[0], h = (y1 - y0) * 0.5 * k[0];
  if (x < x0)
    x = x0 + psi(rng) * w;
  else if (x > x1)
    x = x1 - psi(rng) * w;
  if (y < y0)
    y = y0 + psi(rng) * h;
  else if (y > y1)
    y = y1 - psi(rng) * h;
  return scaled(in.w, x, y);
}

}  // namespace

void add_pack_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "falloff2", .parameters = kFalloff2, .function = falloff2, .kind = K::random},
      {.name = "bwraps", .parameters = kBwraps, .function = bwraps},
      {.name = "unpolar", .function = unpolar},
      {.name = "glynnia", .function = glynnia, .kind = K::random},
      {.name = "tile_log", .parameters = kTileLog, .function = tile_log, .kind = K::random},
      {.name = "tile_hlp", .parameters = kTileHlp, .function = tile_hlp, .kind = K::random},
      {.name = "curl3D", .parameters = kCurl3D, .function = curl_3d},
      {.name = "twoface", .function = twoface},
      {.name = "hypertile2", .parameters = kHypertile2, .function = hypertile2, .kind = K::random},
      {.name = "hypertile3D2",
       .parameters = kHypertile3D2,
       .function = hypertile2,
       .kind = K::random},
      {.name = "gaussian", .function = gaussian, .kind = K::random},
      {.name = "crop", .parameters = kCrop, .function = crop, .kind = K::random},
      {.name = "bTransform", .parameters = kBTransform, .function = b_transform, .kind = K::random},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
