// SPDX-License-Identifier: Apache-2.0
// What the variations share: the paper's polar quantities and its random draws (Draves &
// Reckase, appendix, "Catalog of Variations": r, θ, φ, Ω, Λ, Ψ).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "flame/variations.h"

namespace ifsfx::flame::detail {

inline constexpr double kPi = std::numbers::pi;
// Keeps divisions by r, r² or a parameter finite at 0, as every flame renderer does; small
// enough to change no visible point.
inline constexpr double kEps = 1e-10;

// The paper's polar quantities of a point (appendix: r = √(x² + y²), θ = arctan(x / y),
// φ = arctan(y / x)). Note θ is measured from the y axis: sin θ = x / r, cos θ = y / r.
struct Polar {
  double x, y;
  double r2() const { return x * x + y * y; }
  double r() const { return std::sqrt(r2()); }
  double theta() const { return std::atan2(x, y); }
  double phi() const { return std::atan2(y, x); }
  double sin_theta() const { return x / (r() + kEps); }
  double cos_theta() const { return y / (r() + kEps); }
};

inline Polar polar(const VariationInput& in) {
  return {in.p.x, in.p.y};
}

// Ψ: uniform in [0, 1).
inline double psi(Rng& rng) {
  return rng.uniform();
}
// Ω: 0 or π with equal odds.
inline double omega(Rng& rng) {
  return (rng.next() >> 63) ? kPi : 0.0;
}
// Λ: −1 or 1 with equal odds.
inline double lambda(Rng& rng) {
  return (rng.next() >> 63) ? 1.0 : -1.0;
}
// The paper's cheap Gaussian: Ψ1 + Ψ2 + Ψ3 + Ψ4 − 2 (gaussian_blur, radial_blur, pre_blur).
inline double sum_of_four(Rng& rng) {
  const double a = psi(rng), b = psi(rng), c = psi(rng), d = psi(rng);
  return a + b + c + d - 2.0;
}

// A parameter that picks a mode (a type, a crop mode) as a whole number: rounded to the
// nearest, ⌊v + ½⌋, as Ember and JWildfire read their integer parameters, and kept within int's
// range so that any finite value a file holds converts without undefined behaviour (the
// fuzzer's sanitizers check it).
inline int mode_of(double v) {
  return std::isnan(v) ? 0 : static_cast<int>(std::clamp(std::floor(v + 0.5), -1e9, 1e9));
}

// The {p, q} hyperbolic tiling of hypertile1 and hypertile2: the angle a = 2π/p between its
// Möbius maps and their radius R = 1/√(1 − (cos a − 1)/(cos a + cos(2π/q))) (1 where the root's
// argument is not positive); a p or q of 0 is taken as kEps.
struct HyperTiling {
  double angle, radius;
};
inline HyperTiling hyper_tiling(double p_param, double q_param) {
  const double p = p_param == 0 ? kEps : p_param;
  const double q = q_param == 0 ? kEps : q_param;
  const double pa = 2 * kPi / p, cs = std::cos(pa);
  const double r2 = 1 - (cs - 1) / (cs + std::cos(2 * kPi / q));
  return {pa, r2 > 0 ? 1 / std::sqrt(r2) : 1.0};
}

inline Point scaled(double w, double x, double y) {
  return {w * x, w * y};
}

// The tables of each source file, appended to the registry (flame/variations.cpp).
void add_paper_variations(std::vector<Variation>& out);
void add_flam3_variations(std::vector<Variation>& out);
void add_complex_variations(std::vector<Variation>& out);
void add_more_variations(std::vector<Variation>& out);
void add_pack_variations(std::vector<Variation>& out);
void add_pack2_variations(std::vector<Variation>& out);
void add_pack3_variations(std::vector<Variation>& out);
void add_pack4_variations(std::vector<Variation>& out);
void add_pack5_variations(std::vector<Variation>& out);

// The Möbius map w·(a·z + b)/(c·z + d) of complex a, b, c, d given as params[0..7] (re a, im a,
// re b, ..., im d): flam3's mobius and Apophysis' Mobius plugin, under different parameter names.
inline Point mobius_map(const VariationInput& in) {
  const auto [x, y] = in.p;
  const auto& k = in.params;
  const double ur = k[0] * x - k[1] * y + k[2], ui = k[0] * y + k[1] * x + k[3];
  const double vr = k[4] * x - k[5] * y + k[6], vi = k[4] * y + k[5] * x + k[7];
  const double s = in.w / (vr * vr + vi * vi + kEps);
  return {s * (ur * vr + ui * vi), s * (ui * vr - ur * vi)};
}

}  // namespace ifsfx::flame::detail
