// SPDX-License-Identifier: Apache-2.0
// Affine maps of the plane, f(x, y) = (a x + b y + e, c x + d y + f): the coefficient order of
// Barnsley's IFS-code tables and of Fractint's .ifs files (docs/design.md §1).
#pragma once

#include <array>
#include <cmath>
#include <optional>

namespace ifsfx {

// A point of a plane. Which plane (the IFS plane, a source's unit square, pixels) is said where
// a Point is used.
struct Point {
  double x = 0;
  double y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

struct AffineMap {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  Point operator()(Point p) const { return {a * p.x + b * p.y + e, c * p.x + d * p.y + f}; }

  double det() const { return a * d - b * c; }

  // Contraction factor: the largest singular value of the linear part [[a b][c d]].
  double contraction() const;

  // The inverse map, or nothing when the map is singular (|det| below `eps`), e.g. a fern stem.
  std::optional<AffineMap> inverse(double eps = 1e-12) const;

  // (this ∘ g)(p) = this(g(p)).
  AffineMap compose(const AffineMap& g) const;

  // True when all six coefficients are finite numbers.
  bool finite() const;

  std::array<double, 6> coefficients() const { return {a, b, c, d, e, f}; }
  static AffineMap from_coefficients(const std::array<double, 6>& k) {
    return {k[0], k[1], k[2], k[3], k[4], k[5]};
  }
  friend bool operator==(const AffineMap&, const AffineMap&) = default;
};

// The map taking the rectangle [x0,x1]×[y0,y1] onto [u0,u1]×[v0,v1], axes kept.
AffineMap rectangle_map(double x0, double y0, double x1, double y1, double u0, double v0, double u1,
                        double v1);

}  // namespace ifsfx
