// SPDX-License-Identifier: Apache-2.0
// The complex functions of z = x + i·y that flam3 lists as variations: exp, log and the
// trigonometric and hyperbolic functions with their reciprocals. Each returns w·f(z) written
// out in real and imaginary parts (|cos z|² = (cos 2x + cosh 2y)/2 and the like), so a pole
// gives an infinity, which the chaos game re-seeds, never a trap.
#include <cmath>
#include <numbers>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

Point exp_v(const VariationInput& in, Rng&) {
  const double e = in.w * std::exp(in.p.x);
  return {e * std::cos(in.p.y), e * std::sin(in.p.y)};
}

// The principal logarithm (ln r, φ); Ember's log_base divides ln r by ln base (e: flam3's).
constexpr VariationParameter kLog[] = {{"log_base", std::numbers::e}};
Point log_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double base = std::log(in.params[0]);
  return scaled(in.w, 0.5 * std::log(x * x + y * y) / base, std::atan2(y, x));
}

Point sin_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, std::sin(x) * std::cosh(y), std::cos(x) * std::sinh(y));
}

Point cos_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, std::cos(x) * std::cosh(y), -std::sin(x) * std::sinh(y));
}

Point tan_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 1 / (std::cos(2 * x) + std::cosh(2 * y));
  return scaled(in.w * d, std::sin(2 * x), std::sinh(2 * y));
}

Point sec_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 2 / (std::cos(2 * x) + std::cosh(2 * y));
  return scaled(in.w * d, std::cos(x) * std::cosh(y), std::sin(x) * std::sinh(y));
}

Point csc_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 2 / (std::cosh(2 * y) - std::cos(2 * x));
  return scaled(in.w * d, std::sin(x) * std::cosh(y), -std::cos(x) * std::sinh(y));
}

Point cot_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 1 / (std::cosh(2 * y) - std::cos(2 * x));
  return scaled(in.w * d, std::sin(2 * x), -std::sinh(2 * y));
}

Point sinh_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, std::sinh(x) * std::cos(y), std::cosh(x) * std::sin(y));
}

Point cosh_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, std::cosh(x) * std::cos(y), std::sinh(x) * std::sin(y));
}

Point tanh_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 1 / (std::cos(2 * y) + std::cosh(2 * x));
  return scaled(in.w * d, std::sinh(2 * x), std::sin(2 * y));
}

Point sech_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 2 / (std::cos(2 * y) + std::cosh(2 * x));
  return scaled(in.w * d, std::cos(y) * std::cosh(x), -std::sin(y) * std::sinh(x));
}

Point csch_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 2 / (std::cosh(2 * x) - std::cos(2 * y));
  return scaled(in.w * d, std::sinh(x) * std::cos(y), -std::cosh(x) * std::sin(y));
}

Point coth_v(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = 1 / (std::cosh(2 * x) - std::cos(2 * y));
  return scaled(in.w * d, std::sinh(2 * x), std::sin(2 * y));
}

}  // namespace

void add_complex_variations(std::vector<Variation>& out) {
  const Variation rows[] = {
      {.name = "exp", .function = exp_v},   {.name = "log", .parameters = kLog, .function = log_v},
      {.name = "sin", .function = sin_v},   {.name = "cos", .function = cos_v},
      {.name = "tan", .function = tan_v},   {.name = "sec", .function = sec_v},
      {.name = "csc", .function = csc_v},   {.name = "cot", .function = cot_v},
      {.name = "sinh", .function = sinh_v}, {.name = "cosh", .function = cosh_v},
      {.name = "tanh", .function = tanh_v}, {.name = "sech", .function = sech_v},
      {.name = "csch", .function = csch_v}, {.name = "coth", .function = coth_v},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
