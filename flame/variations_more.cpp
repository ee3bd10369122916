// SPDX-License-Identifier: Apache-2.0
// Variations beyond flam3's set that the example packs of Fractorium (Ember), JWildfire and
// Apophysis 7X use most (docs/flames.md counts them), from their plugins' published
// definitions, and the 3-D ones whose effect on the plane is nil or whose z = 0 slice is a 2-D
// variation: ifsfx's flames are planar, every point has z = 0.
#include <algorithm>
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

Point linear_v(const VariationInput& in, Rng&) {
  return scaled(in.w, in.p.x, in.p.y);
}

// Acts on z only: adds nothing to the sum (flame/xform_eval.h).
Point z_only(const VariationInput&, Rng&) {
  return {0, 0};
}

// spherical3D at z = 0: (x, y) / r².
Point spherical_3d(const VariationInput& in, Rng&) {
  const double k = in.w / (polar(in).r2() + kEps);
  return {k * in.p.x, k * in.p.y};
}

// A random offset whose radius has the density sin-shaped by `power` (1: acos(2Ψ − 1)/π).
constexpr VariationParameter kSineblur[] = {{"sineblur_power", 1}};
Point sineblur(const VariationInput& in, Rng& rng) {
  const double pw = std::max(in.params[0], 0.0), a = 2 * kPi * psi(rng);
  const double u = pw == 1 ? psi(rng) : std::pow(psi(rng), pw);
  const double r = in.w * std::acos(2 * u - 1) / kPi;
  return {r * std::cos(a), r * std::sin(a)};
}

// The epispiral r = 1/cos(nθ) (thickened by a random amount, moved in by `holes`).
constexpr VariationParameter kEpispiral[] = {
    {"epispiral_n", 6}, {"epispiral_thickness", 0}, {"epispiral_holes", 1}};
Point epispiral(const VariationInput& in, Rng& rng) {
  const double n = in.params[0], thickness = in.params[1], holes = in.params[2];
  const double theta = polar(in).phi(), d = std::cos(n * theta);
  const double spread = std::abs(thickness) > kEps ? psi(rng) * thickness : 1.0;
  const double t = -holes + spread / d;
  return scaled(in.w * t, std::cos(theta), std::sin(theta));
}

// julia3D at z = 0: julian with dist 1, r^(1/power) on a random branch.
constexpr VariationParameter kJulia3D[] = {{"julia3D_power", 2}};
Point julia_3d(const VariationInput& in, Rng& rng) {
  const double pw = in.params[0];
  const Polar q = polar(in);
  const double branch = std::trunc(std::abs(pw) * psi(rng));
  const double a = (q.phi() + 2 * kPi * branch) / pw;
  const double r = in.w * std::pow(q.r2(), (1 / pw - 1) / 2) * q.r();
  return {r * std::cos(a), r * std::sin(a)};
}

// The plane onto the unit hemisphere seen from above: (x, y)/√(r² + 1).
Point hemisphere(const VariationInput& in, Rng&) {
  const double k = in.w / std::sqrt(polar(in).r2() + 1);
  return {k * in.p.x, k * in.p.y};
}

// A uniform point of the square [−1, 1]² carried onto the disc by its perimeter position.
Point blur_circle(const VariationInput& in, Rng& rng) {
  const double x = 2 * psi(rng) - 1, y = 2 * psi(rng) - 1;
  const double ax = std::abs(x), ay = std::abs(y);
  double perimeter, side;
  if (ax >= ay) {
    perimeter = x >= ay ? ax + y : 5 * ax - y;
    side = ax;
  } else {
    perimeter = y >= ax ? 3 * ay - x : 7 * ay + x;
    side = ay;
  }
  const double r = in.w * side, a = kPi / 4 * perimeter / (side + kEps) - kPi / 4;
  return {r * std::cos(a), r * std::sin(a)};
}

// The point moved a random part of `length` along `angle` (radians).
constexpr VariationParameter kBlurLinear[] = {{"blur_linear_length", 0}, {"blur_linear_angle", 0}};
Point blur_linear(const VariationInput& in, Rng& rng) {
  const double r = in.params[0] * psi(rng), a = in.params[1];
  return scaled(in.w, in.p.x + r * std::cos(a), in.p.y + r * std::sin(a));
}

// The point scaled about (x0, y0) by a random factor in [1, 1 + length].
constexpr VariationParameter kBlurZoom[] = {
    {"blur_zoom_length", 0}, {"blur_zoom_x", 0}, {"blur_zoom_y", 0}};
Point blur_zoom(const VariationInput& in, Rng& rng) {
  const double z = 1 + in.params[0] * psi(rng), cx = in.params[1], cy = in.params[2];
  return scaled(in.w, (in.p.x - cx) * z + cx, (in.p.y - cy) * z + cy);
}

// Apophysis' Mobius plugin: flam3's mobius under the plugin's own parameter names.
constexpr VariationParameter kMobiusPlugin[] = {
    {"Mobius_Re_A", 1}, {"Mobius_Im_A", 0}, {"Mobius_Re_B", 0}, {"Mobius_Im_B", 0},
    {"Mobius_Re_C", 0}, {"Mobius_Im_C", 0}, {"Mobius_Re_D", 1}, {"Mobius_Im_D", 0}};
Point mobius_plugin(const VariationInput& in, Rng&) {
  return mobius_map(in);
}

}  // namespace

void add_more_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "linear3D", .function = linear_v},
      {.name = "flatten", .function = z_only, .kind = K::flat_3d},
      {.name = "zscale", .function = z_only, .kind = K::flat_3d},
      {.name = "ztranslate", .function = z_only, .kind = K::flat_3d},
      {.name = "zcone", .function = z_only, .kind = K::flat_3d},
      {.name = "zblur", .function = z_only, .kind = K::flat_3d},
      {.name = "Spherical3D", .function = spherical_3d},
      {.name = "sineblur",
       .parameters = kSineblur,
       .function = sineblur,
       .kind = K::random,
       .assign = Assign::add},
      {.name = "epispiral", .parameters = kEpispiral, .function = epispiral, .kind = K::random},
      {.name = "julia3D", .parameters = kJulia3D, .function = julia_3d, .kind = K::random},
      {.name = "hemisphere", .function = hemisphere},
      {.name = "blur_circle", .function = blur_circle, .kind = K::random, .assign = Assign::add},
      {.name = "blur_linear",
       .parameters = kBlurLinear,
       .function = blur_linear,
       .kind = K::random},
      {.name = "blur_zoom", .parameters = kBlurZoom, .function = blur_zoom, .kind = K::random},
      {.name = "Mobius", .parameters = kMobiusPlugin, .function = mobius_plugin},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
