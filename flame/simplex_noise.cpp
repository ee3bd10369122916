// SPDX-License-Identifier: Apache-2.0
#include "flame/detail/simplex_noise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "ifs/rng.h"

namespace ifsfx::flame::detail {
namespace {

struct Vec3 {
  double x, y, z;
};

constexpr std::size_t kGradients = 256;
using Gradients = std::array<Vec3, kGradients>;

// kGradients unit vectors, uniform on the sphere (z = 2u − 1 and a uniform angle about z: the
// sphere's area is uniform in z, Archimedes' hat-box theorem), from a fixed seed.
Gradients make_gradients() {
  Gradients g{};
  Rng rng(0x5eed'c4ac'c1e0ULL);
  for (Vec3& v : g) {
    const double z = 2 * rng.uniform() - 1, a = 2 * std::numbers::pi * rng.uniform();
    const double s = std::sqrt(1 - z * z);
    v = {s * std::cos(a), s * std::sin(a), z};
  }
  return g;
}

// Built once, never changed: constant data, like a table in the source.
const Gradients& gradients() {
  static const Gradients g = make_gradients();
  return g;
}

// Lattice corner (i, j, k)'s kernel at the offset d from it: (0.6 − |d|²)⁴·(g·d), g its
// gradient (the table's entry a hash of the corner picks), 0 beyond |d|² = 0.6.
double corner(const Gradients& table, Vec3 d, std::int64_t i, std::int64_t j, std::int64_t k) {
  double f = 0.6 - d.x * d.x - d.y * d.y - d.z * d.z;
  if (f <= 0) return 0;
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
  const std::uint64_t h = mix64(u(i) * 0x9e3779b97f4a7c15ULL ^ u(j) * 0xc2b2ae3d27d4eb4fULL ^
                                u(k) * 0x165667b19e3779f9ULL);
  const Vec3& g = table[h % kGradients];
  f *= f;
  return f * f * (g.x * d.x + g.y * d.y + g.z * d.z);
}

}  // namespace

double simplex_noise(double x, double y, double z) {
  constexpr double kUnskew = 1.0 / 6;
  const double s = (x + y + z) / 3;
  const double fi = std::floor(x + s), fj = std::floor(y + s), fk = std::floor(z + s);
  const double t = (fi + fj + fk) * kUnskew;
  const double x0 = x - (fi - t), y0 = y - (fj - t), z0 = z - (fk - t);
  // The tetrahedron holding (x0, y0, z0): its second corner is one step along the axis of the
  // largest component, its third one step along all but the smallest (Gustavson's table).
  int i1 = 0, j1 = 0, k1 = 0, i2 = 1, j2 = 1, k2 = 1;
  if (x0 >= y0) {
    if (y0 >= z0) {
      i1 = 1, k2 = 0;  // x ≥ y ≥ z
    } else if (x0 >= z0) {
      i1 = 1, j2 = 0;  // x ≥ z > y
    } else {
      k1 = 1, j2 = 0;  // z > x ≥ y
    }
  } else if (y0 < z0) {
    k1 = 1, i2 = 0;  // z > y > x
  } else if (x0 < z0) {
    j1 = 1, i2 = 0;  // y ≥ z > x
  } else {
    j1 = 1, k2 = 0;  // y > x ≥ z
  }
  // The corner's whole coordinates, for its hash only: beyond ±2⁶² (a noise read at 10¹⁹ and
  // more, or not a number) the noise means nothing anyway; the clamp keeps the conversion
  // defined.
  const auto whole = [](double v) {
    return std::isnan(v) ? 0 : static_cast<std::int64_t>(std::clamp(v, -0x1p62, 0x1p62));
  };
  const std::int64_t i = whole(fi), j = whole(fj), k = whole(fk);
  const Gradients& g = gradients();
  double n = corner(g, {x0, y0, z0}, i, j, k);
  n += corner(g, {x0 - i1 + kUnskew, y0 - j1 + kUnskew, z0 - k1 + kUnskew}, i + i1, j + j1, k + k1);
  n += corner(g, {x0 - i2 + 2 * kUnskew, y0 - j2 + 2 * kUnskew, z0 - k2 + 2 * kUnskew}, i + i2,
              j + j2, k + k2);
  n += corner(g, {x0 - 0.5, y0 - 0.5, z0 - 0.5}, i + 1, j + 1, k + 1);
  return 32 * n;
}

}  // namespace ifsfx::flame::detail
