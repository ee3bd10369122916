// SPDX-License-Identifier: Apache-2.0
#include "ifs/affine_map.h"

namespace ifsfx {

double AffineMap::contraction() const {
  // Largest singular value of M = [[a b][c d]]: sqrt of the largest eigenvalue of MᵀM.
  const double p = a * a + c * c;  // (MᵀM)11
  const double q = a * b + c * d;  // (MᵀM)12
  const double r = b * b + d * d;  // (MᵀM)22
  const double half_trace = 0.5 * (p + r);
  const double disc = std::sqrt(0.25 * (p - r) * (p - r) + q * q);
  return std::sqrt(half_trace + disc);
}

std::optional<AffineMap> AffineMap::inverse(double eps) const {
  const double dt = det();
  if (!(std::abs(dt) > eps)) return std::nullopt;
  const double ia = d / dt, ib = -b / dt, ic = -c / dt, id = a / dt;
  return AffineMap{ia, ib, ic, id, -(ia * e + ib * f), -(ic * e + id * f)};
}

AffineMap AffineMap::compose(const AffineMap& g) const {
  return {a * g.a + b * g.c, a * g.b + b * g.d,     c * g.a + d * g.c,
          c * g.b + d * g.d, a * g.e + b * g.f + e, c * g.e + d * g.f + f};
}

bool AffineMap::finite() const {
  for (double k : coefficients())
    if (!std::isfinite(k)) return false;
  return true;
}

AffineMap rectangle_map(double x0, double y0, double x1, double y1, double u0, double v0, double u1,
                        double v1) {
  const double sx = (u1 - u0) / (x1 - x0);
  const double sy = (v1 - v0) / (y1 - y0);
  return {sx, 0, 0, sy, u0 - sx * x0, v0 - sy * y0};
}

}  // namespace ifsfx
