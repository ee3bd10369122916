// SPDX-License-Identifier: Apache-2.0
#include "collage/map_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ifsfx::collage {

namespace {

double logistic(double u) {
  return 1 / (1 + std::exp(-u));
}
double logit(double p) {
  return std::log(p / (1 - p));
}

// The 2×2 SVD of [[a b][c d]] = R(θ) diag(σ₁, s σ₂) R(φ), s = sign of det (Blinn's closed form:
// the matrix is the sum of a similarity E and an anti-similarity F).
struct Decomposition {
  double theta = 0, phi = 0, s1 = 0, s2 = 0;
  bool reflected = false;
};

Decomposition decompose(const AffineMap& m) {
  const double e = (m.a + m.d) / 2, f = (m.a - m.d) / 2;
  const double g = (m.c + m.b) / 2, h = (m.c - m.b) / 2;
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  const double a1 = std::atan2(g, f), a2 = std::atan2(h, e);
  // M = R((a2 + a1)/2) · diag(q + r, q − r) · R((a2 − a1)/2).
  Decomposition out;
  out.theta = (a2 + a1) / 2;
  out.phi = (a2 - a1) / 2;
  out.s1 = q + r;
  const double s2 = q - r;
  out.reflected = s2 < 0;
  out.s2 = std::abs(s2);
  return out;
}

}  // namespace

std::vector<double> to_coordinates(std::span<const AffineMap> maps, MapCoordinates& frame) {
  std::vector<double> x;
  frame.reflected.clear();
  const double low = 1e-3 * frame.max_factor, high = 0.999 * frame.max_factor;
  for (const AffineMap& m : maps) {
    const Decomposition d = decompose(m);
    frame.reflected.push_back(d.reflected);
    const Point t = m(frame.centre);
    x.insert(x.end(), {d.theta, d.phi, logit(std::clamp(d.s1, low, high) / frame.max_factor),
                       logit(std::clamp(d.s2, low, high) / frame.max_factor),
                       t.x / kTranslationUnit, t.y / kTranslationUnit});
  }
  return x;
}

std::vector<AffineMap> from_coordinates(std::span<const double> x, const MapCoordinates& frame) {
  std::vector<AffineMap> maps;
  for (std::size_t i = 0, n = 0; i + 6 <= x.size(); i += 6, ++n) {
    const double s1 = frame.max_factor * logistic(x[i + 2]);
    const double s2 = frame.max_factor * logistic(x[i + 3]) *
                      (n < frame.reflected.size() && frame.reflected[n] ? -1 : 1);
    const double ct = std::cos(x[i]), st = std::sin(x[i]);
    const double cp = std::cos(x[i + 1]), sp = std::sin(x[i + 1]);
    // R(θ) · diag(s1, s2) · R(φ), R(α) = [[cos −sin][sin cos]].
    AffineMap m;
    m.a = ct * s1 * cp - st * s2 * sp;
    m.b = -ct * s1 * sp - st * s2 * cp;
    m.c = st * s1 * cp + ct * s2 * sp;
    m.d = -st * s1 * sp + ct * s2 * cp;
    const Point t{x[i + 4] * kTranslationUnit, x[i + 5] * kTranslationUnit};
    m.e = t.x - (m.a * frame.centre.x + m.b * frame.centre.y);
    m.f = t.y - (m.c * frame.centre.x + m.d * frame.centre.y);
    maps.push_back(m);
  }
  return maps;
}

}  // namespace ifsfx::collage
