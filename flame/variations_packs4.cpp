// SPDX-License-Identifier: Apache-2.0
// The last of the variations Fractorium's example packs use that a 2-D registry function can
// be: y (a sum of radial shapes) and falloff3 (falloff2's successor, at z = 0), each from the
// formula as docs/flames.md states it.
#include <algorithm>
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

// y's four shapes, each a function of the angle φ only, summed with their weights into a
// total T: the point goes to w·T²/r on its own ray.
//   hypergon: a = mod(|φ|, 2π/n) − π/n, s = tan²a + 1, d = √(1 + r_h²): 1 where s ≥ d²,
//             else (d − √(d² − s))/√s (a polygon of n sides bent into circular arcs)
//   star:     b = tan|mod(|φ|, 2π/n) − π/n|: √(tan²σ·(1 + b²))/(b + tan σ), σ the slope
//             (a slope of π/2 or more taken as π/2 − 0.05, where tan σ is finite)
//   lituus:   |φ/π + 1|^(−a)
//   super:    (|cos(mφ/4)|^n2 + |sin(mφ/4)|^n3)^(−1/n1) (Gielis' superformula)
constexpr VariationParameter kY[] = {
    {"y_hypergon", 0},   {"y_hypergon_n", 4}, {"y_hypergon_r", 1}, {"y_star", 0},  {"y_star_n", 5},
    {"y_star_slope", 2}, {"y_lituus", 0},     {"y_lituus_a", 1},   {"y_super", 0}, {"y_super_m", 1},
    {"y_super_n1", 1},   {"y_super_n2", 1},   {"y_super_n3", 1}};
double y_total(std::span<const double> k, double phi) {
  double total = 0;
  if (k[0] != 0) {
    const double n = k[1] == 0 ? kEps : k[1];
    const double a = std::fmod(std::abs(phi), 2 * kPi / n) - kPi / n;
    const double s = std::tan(a) * std::tan(a) + 1, d2 = 1 + k[2] * k[2];
    total += s >= d2 ? k[0] : k[0] * (std::sqrt(d2) - std::sqrt(d2 - s)) / std::sqrt(s);
  }
  if (k[3] != 0) {
    const double n = k[4] == 0 ? kEps : k[4];
    const double b = std::tan(std::abs(std::fmod(std::abs(phi), 2 * kPi / n) - kPi / n));
    const double ts = std::tan(k[5] >= kPi / 2 - 1e-6 ? kPi / 2 - 0.05 : k[5]);
    total += k[3] * std::sqrt(ts * ts * (1 + b * b)) / std::abs(b + ts);
  }
  if (k[6] != 0) total += k[6] * std::pow(std::abs(phi / kPi + 1), -k[7]);
  if (k[8] != 0) {
    const double t = phi * k[9] / 4, n1 = k[10] == 0 ? kEps : k[10];
    total += k[8] * std::pow(std::pow(std::abs(std::cos(t)), k[11]) +
                                 std::pow(std::abs(std::sin(t)), k[12]),
                             -1 / n1);
  }
  return total;
}
Point y_shapes(const VariationInput& in, Rng&) {
  const double phi = polar(in).phi(), total = y_total(in.params, phi);
  double r = polar(in).r();
  if (r == 0) r = kEps;
  return scaled(in.w * total * total / r, std::cos(phi), std::sin(phi));
}

// falloff3 at z = 0: falloff2's blur, its distance d measured from (center_x, center_y,
// center_z) as a circle (blur_shape 0) or a square (1, the largest coordinate difference),
// dist = max((d or max(1 − d, 0) with invert_distance − min_distance)·0.04·blur_strength, 0);
// four draws u_x, u_y, u_z, u_c in [−½, ½), in that order. blur_type 0 (Gaussian): p moved by
// dist·u_x·cos(2π·dist·u_y)·(mul_x·cos(π·dist·u_z), mul_y·sin(π·dist·u_z)); 1 (radial): the
// radius moved by mul_x·u_x·dist, the angle by mul_y·u_y·dist, and the result times
// cos(mul_z·u_z·dist); 2 and others (logarithmic): each coordinate moved by L(mul)·S(u)·c,
// L(v) = (e + ln(e·v))/4·sign v, S(u) = ln(e·(|u| + 1))/e·sign u (both 0 at 0), c = dist +
// alpha·(L(dist) − dist). Times w. mul_c, the colour's move, is read but not applied.
constexpr VariationParameter kFalloff3[] = {
    {"falloff3_blur_type", 0},      {"falloff3_blur_shape", 0},      {"falloff3_blur_strength", 1},
    {"falloff3_min_distance", 0.5}, {"falloff3_invert_distance", 0}, {"falloff3_mul_x", 1},
    {"falloff3_mul_y", 1},          {"falloff3_mul_z", 0},           {"falloff3_mul_c", 0},
    {"falloff3_center_x", 0},       {"falloff3_center_y", 0},        {"falloff3_center_z", 0},
    {"falloff3_alpha", 0}};
double log_map(double v) {
  return v == 0 ? 0
                : (std::numbers::e + std::log(std::abs(v) * std::numbers::e)) * 0.25 *
                      (v < 0 ? -1 : 1);
}
double log_scale(double u) {
  return u == 0
             ? 0
             : std::log((std::abs(u) + 1) * std::numbers::e) / std::numbers::e * (u < 0 ? -1 : 1);
}
Point falloff3(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double ux = psi(rng) - 0.5, uy = psi(rng) - 0.5, uz = psi(rng) - 0.5;
  (void)psi(rng);  // the colour's draw
  const auto [x, y] = in.p;
  const double dx = x - k[9], dy = y - k[10], dz = k[11];
  const double d = k[1] == 0 ? std::sqrt(dx * dx + dy * dy + dz * dz)
                             : std::max({std::abs(dx), std::abs(dy), std::abs(dz)});
  const double rmax = 0.04 * k[2];
  const double dist = std::max(((k[4] != 0 ? std::max(1 - d, 0.0) : d) - k[3]) * rmax, 0.0);
  const int type = mode_of(k[0]);
  if (type == 0) {
    const double sigma = dist * uy * 2 * kPi, phi = dist * uz * kPi, rad = dist * ux;
    return scaled(in.w, x + k[5] * rad * std::cos(sigma) * std::cos(phi),
                  y + k[6] * rad * std::cos(sigma) * std::sin(phi));
  }
  if (type == 1) {
    if (x == 0 && y == 0) return {0, 0};
    const double r = std::hypot(x, y) + k[5] * ux * dist;
    const double phi = std::atan2(y, x) + k[6] * uy * dist, sigma = k[7] * uz * dist;
    return scaled(in.w * r * std::cos(sigma), std::cos(phi), std::sin(phi));
  }
  const double c = rmax <= 1e-20 ? dist : dist + k[12] * (log_map(dist) - dist);
  return scaled(in.w, x + log_map(k[5]) * log_scale(ux) * c, y + log_map(k[6]) * log_scale(uy) * c);
}

}  // namespace

void add_pack4_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "y", .parameters = kY, .function = y_shapes},
      {.name = "falloff3", .parameters = kFalloff3, .function = falloff3, .kind = K::random},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
