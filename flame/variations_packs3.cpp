// SPDX-License-Identifier: Apache-2.0
// The variations each of which one flame of Fractorium's example packs still lacked
// (docs/flames.md): mirror_x/y, rotate_x/y (their z = 0 slice), circlecrop, bcircle, shredlin,
// gnarly, blur3D (its projection), rblur, hypertile1, bubble2 (its z = 0 slice), wdisc and
// eJulia, each from the formula as docs/flames.md states it.
#include <algorithm>
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

// mirror_x, mirror_y: one coordinate's absolute value, its sign drawn (Λ). The weight only
// switches the variation on: it does not scale the point (Ember's rule).
Point mirror_x(const VariationInput& in, Rng& rng) {
  return {lambda(rng) * std::abs(in.p.x), in.p.y};
}
Point mirror_y(const VariationInput& in, Rng& rng) {
  return {in.p.x, lambda(rng) * std::abs(in.p.y)};
}

// rotate_x, rotate_y: the 3-D turn by w·π/2 about the x (y) axis, at z = 0: the other
// coordinate times cos(w·π/2). The weight is the angle, not a scale.
Point rotate_x(const VariationInput& in, Rng&) {
  return {in.p.x, std::cos(in.w * kPi / 2) * in.p.y};
}
Point rotate_y(const VariationInput& in, Rng&) {
  return {std::cos(in.w * kPi / 2) * in.p.x, in.p.y};
}

// circlecrop: d = p − c; inside the circle |d| ≤ radius, w·d + c; outside, the origin with
// `zero`, else w·ρ·d/|d| + c, ρ = radius + Ψ·½·clamp(scatter_area, −1, 1) (Ψ always drawn).
constexpr VariationParameter kCirclecrop[] = {{"circlecrop_radius", 1},
                                              {"circlecrop_x", 0},
                                              {"circlecrop_y", 0},
                                              {"circlecrop_scatter_area", 0},
                                              {"circlecrop_zero", 1}};
Point circlecrop(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double dx = in.p.x - k[1], dy = in.p.y - k[2], r = std::hypot(dx, dy);
  const double rho = k[0] + psi(rng) * 0.5 * std::clamp(k[3], -1.0, 1.0);
  if (r <= k[0]) return {in.w * dx + k[1], in.w * dy + k[2]};
  if (k[4] != 0) return {0, 0};
  const double a = std::atan2(dy, dx);
  return {in.w * rho * std::cos(a) + k[1], in.w * rho * std::sin(a) + k[2]};
}

// bcircle: q = scale·p; inside the unit circle w·q; outside, with a border width b ≠ 0, w·(1 +
// 0.2·|b|·Ψ) on q's ray (a ring just outside the circle), else the origin.
constexpr VariationParameter kBcircle[] = {{"bcircle_scale", 1}, {"bcircle_borderwidth", 0}};
Point bcircle(const VariationInput& in, Rng& rng) {
  const double x = in.p.x * in.params[0], y = in.p.y * in.params[0];
  if (std::hypot(x, y) <= 1) return scaled(in.w, x, y);
  if (in.params[1] == 0) return {0, 0};
  const double rho = in.w * (0.2 * std::abs(in.params[1]) * psi(rng) + 1), a = std::atan2(y, x);
  return {rho * std::cos(a), rho * std::sin(a)};
}

// shredlin: each coordinate cut into strips of `distance`; t = x/distance, its whole part n
// = trunc(t) and fraction f = t − n: w·distance·(f·width + n + (½ − [x < 0])·(1 − width)): each
// strip narrowed to `width` of itself about its middle.
constexpr VariationParameter kShredlin[] = {{"shredlin_xdistance", 1},
                                            {"shredlin_xwidth", 0.5},
                                            {"shredlin_ydistance", 1},
                                            {"shredlin_ywidth", 0.5}};
double shred(double v, double distance, double width) {
  if (distance == 0) distance = kEps;
  const double t = v / distance, n = std::trunc(t);
  return distance * ((t - n) * width + n + ((v < 0 ? -0.5 : 0.5) * (1 - width)));
}
Point shredlin(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  return scaled(in.w, shred(in.p.x, k[0], k[1]), shred(in.p.y, k[2], k[3]));
}

// gnarly: cells of side s centred at c = (⌊x/s⌋ + ½, ⌊y/s⌋ + ½)·s; in the disc of radius s/2
// about c, l = p − c is turned clockwise by twist·ln(|l|²/(s/2)²): a logarithmic whirl that
// is still at the rim and turns ever faster towards c (c itself stays).
constexpr VariationParameter kGnarly[] = {{"gnarly_cellsize", 1}, {"gnarly_twist", 1}};
Point gnarly(const VariationInput& in, Rng&) {
  const double s = in.params[0];
  auto [x, y] = in.p;
  if (s != 0) {
    const double cx = (std::floor(x / s) + 0.5) * s, cy = (std::floor(y / s) + 0.5) * s;
    const double lx = x - cx, ly = y - cy, l2 = lx * lx + ly * ly;
    double r2 = 0.25 * s * s;
    if (r2 == 0) r2 = kEps;
    if (l2 <= r2 && l2 > 0) {
      const double theta = in.params[1] * std::log(l2 / r2);
      const double sn = std::sin(theta), cs = std::cos(theta);
      x = cx + cs * lx + sn * ly;
      y = cy - sn * lx + cs * ly;
    }
  }
  return scaled(in.w, x, y);
}

// blur3D seen from above: a 3-D Gaussian-like blur (radius w·(Ψ1 + Ψ2 + Ψ3 + Ψ4 − 2) in a
// random direction: azimuth α = 2πΨ0 drawn first, polar angle β = πΨ5 last) projected on the
// plane: ρ·sin β·(cos α, sin α).
Point blur_3d(const VariationInput& in, Rng& rng) {
  const double alpha = 2 * kPi * psi(rng), r = in.w * sum_of_four(rng);
  const double beta = kPi * psi(rng);
  return {r * std::sin(beta) * std::cos(alpha), r * std::sin(beta) * std::sin(alpha)};
}

// rblur: p moved by a blur that grows with the distance from (center_x, center_y) beyond
// `offset`: ρ = 2·strength·max(|p − c| − offset, 0), w·(x + (Ψ1 − ½)·ρ, y + (Ψ2 − ½)·ρ).
constexpr VariationParameter kRblur[] = {
    {"rblur_strength", 1}, {"rblur_offset", 1}, {"rblur_center_x", 0}, {"rblur_center_y", 0}};
Point rblur(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double d = std::hypot(in.p.x - k[2], in.p.y - k[3]);
  const double rho = 2 * k[0] * std::max(d - k[1], 0.0);
  const double u = psi(rng) - 0.5, v = psi(rng) - 0.5;
  return scaled(in.w, in.p.x + u * rho, in.p.y + v * rho);
}

// hypertile1: the {p, q} tiling's other Möbius form, w·(z + ρ̄)/(ρ·z + 1), ρ = R·e^{it}, t a
// random multiple k of 2π/p (k = ⌊32767·Ψ⌋, as hypertile2), R as hypertile2's.
constexpr VariationParameter kHypertile1[] = {{"hypertile1_p", 3}, {"hypertile1_q", 7}};
Point hypertile1(const VariationInput& in, Rng& rng) {
  const auto [pa, big_r] = hyper_tiling(in.params[0], in.params[1]);
  const double t = std::floor(32767 * psi(rng)) * pa;
  const double re = big_r * std::cos(t), im = big_r * std::sin(t);
  const auto [x, y] = in.p;
  const double a = x + re, b = y - im, c = re * x - im * y + 1, d = re * y + im * x;
  const double den = c * c + d * d, vr = in.w / (den == 0 ? kEps : den);
  return {vr * (a * c + b * d), vr * (b * c - a * d)};
}

// bubble2 at z = 0: bubble's w·p/(r²/4 + 1) with x and y scaled by bubble2_x and bubble2_y.
constexpr VariationParameter kBubble2[] = {{"bubble2_x", 1}, {"bubble2_y", 1}, {"bubble2_z", 0}};
Point bubble2(const VariationInput& in, Rng&) {
  const double s = in.w / (polar(in).r2() / 4 + 1);
  return {s * in.p.x * in.params[0], s * in.p.y * in.params[1]};
}

// wdisc: radius φ/π, angle π/(r + 1) (π minus it where φ > 0): w·(φ/π)·(cos a, sin a).
Point wdisc(const VariationInput& in, Rng&) {
  const double s = polar(in).phi() / kPi;
  double a = kPi / (polar(in).r() + 1);
  if (s > 0) a = kPi - a;
  return scaled(in.w * s, std::cos(a), std::sin(a));
}

// eJulia: julian's roots in elliptic coordinates. z = cosh(μ + iν) (foci ±1): μ =
// acosh(xmax), xmax = max((√((x + 1)² + y²) + √((x − 1)² + y²))/2, 1), ν = ±acos(x/xmax)
// (the sign of y); then μ/power and ν/power + 2π/power·⌊Ψ·power⌋, back as w·(cosh μ·cos ν,
// sinh μ·sin ν). A negative power first inverts x and r² (x/r², 1/r²) and keeps y's sign.
constexpr VariationParameter kEJulia[] = {{"eJulia_power", 2}};
Point e_julia(const VariationInput& in, Rng& rng) {
  const double power = in.params[0] == 0 ? kEps : in.params[0];
  double r2 = polar(in).r2(), x = in.p.x;
  if (power < 0) {
    r2 = 1 / (r2 == 0 ? kEps : r2);
    x *= r2;
  }
  const auto safe_sqrt = [](double v) { return v > 0 ? std::sqrt(v) : 0.0; };
  const double xmax = std::max((safe_sqrt(r2 + 1 + 2 * x) + safe_sqrt(r2 + 1 - 2 * x)) / 2, 1.0);
  double nu = std::acos(std::clamp(x / xmax, -1.0, 1.0));
  if (in.p.y < 0) nu = -nu;
  nu = nu / power + 2 * kPi / power * std::floor(psi(rng) * power);
  const double mu = std::acosh(xmax) / power;
  return {in.w * std::cosh(mu) * std::cos(nu), in.w * std::sinh(mu) * std::sin(nu)};
}

// circleblur: a point uniform in the disc of radius w: √Ψ1·(cos 2πΨ2, sin 2πΨ2)·w (the area
// grows as the square of the radius). Added to the point in pre_/post_ lists (Ember's rule).
Point circleblur(const VariationInput& in, Rng& rng) {
  const double rho = in.w * std::sqrt(psi(rng)), a = 2 * kPi * psi(rng);
  return {rho * std::cos(a), rho * std::sin(a)};
}

// pow_block: z^(n/d) with its d branches: w·r^P·(cos θ, sin θ), θ = n·(φ + root·2π·⌊Ψ·d⌋)/d,
// P = n/(d·correctn/correctd) (the radius' power may be corrected apart from the angle's).
constexpr VariationParameter kPowBlock[] = {{"pow_block_numerator", 3},
                                            {"pow_block_denominator", 2},
                                            {"pow_block_root", 1},
                                            {"pow_block_correctn", 1},
                                            {"pow_block_correctd", 1}};
Point pow_block(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double d = k[1] == 0 ? kEps : k[1];
  double p_den = d * k[3] / k[4];
  if (p_den == 0) p_den = kEps;
  const double rho = in.w * std::pow(polar(in).r2(), 0.5 * k[0] / p_den);
  const double theta = (polar(in).phi() / d + k[2] * 2 * kPi * std::floor(psi(rng) * d) / d) * k[0];
  return {rho * std::cos(theta), rho * std::sin(theta)};
}

}  // namespace

void add_pack3_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "mirror_x", .function = mirror_x, .kind = K::random},
      {.name = "mirror_y", .function = mirror_y, .kind = K::random},
      {.name = "rotate_x", .function = rotate_x},
      {.name = "rotate_y", .function = rotate_y},
      {.name = "circlecrop", .parameters = kCirclecrop, .function = circlecrop, .kind = K::random},
      {.name = "bcircle", .parameters = kBcircle, .function = bcircle, .kind = K::random},
      {.name = "shredlin", .parameters = kShredlin, .function = shredlin},
      {.name = "gnarly", .parameters = kGnarly, .function = gnarly},
      {.name = "blur3D", .function = blur_3d, .kind = K::random, .assign = Assign::add},
      {.name = "rblur", .parameters = kRblur, .function = rblur, .kind = K::random},
      {.name = "hypertile1", .parameters = kHypertile1, .function = hypertile1, .kind = K::random},
      {.name = "bubble2", .parameters = kBubble2, .function = bubble2},
      {.name = "wdisc", .function = wdisc},
      {.name = "eJulia", .parameters = kEJulia, .function = e_julia, .kind = K::random},
      {.name = "circleblur", .function = circleblur, .kind = K::random, .assign = Assign::add},
      {.name = "pow_block", .parameters = kPowBlock, .function = pow_block, .kind = K::random},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
