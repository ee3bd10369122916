// SPDX-License-Identifier: Apache-2.0
#include "flame/detail/simplex_noise.h"

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

// kGradients unit vectors, uniform on the sphere (z = 2u − 1 and a uniform angle about z: the
// sphere's area is uniform in z, Archimedes' hat-box theorem), from a fixed seed.
std::array<Vec3, kGradients> make_gradients() {
  std::array<Vec3, kGradients> g{};
  Rng rng(0x5eed'c4ac'c1e0ULL);
  for (Vec3& v : g) {
    const double z = 2 * rng.uniform() - 1, a = 2 * std::numbers::pi * rng.uniform();
    const double s = std::sqrt(1 - z * z);
    v = {s * std::cos(a), s * std::sin(a), z};
  }
  return g;
}

// Built once, never changed: constant data, like a table in the source.
const std::array<Vec3, kGradients>& gradients() {
  static const std::array<Vec3, kGradients> g = make_gradients();
  return g;
}

// The gradient of lattice corner (i, j, k).
const Vec3& gradient(std::int64_t i, std::int64_t j, std::int64_t k) {
  const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
  const std::uint64_t h = mix64(u(i) * 0x9e3779b97f4a7c15ULL ^ u(j) * 0xc2b2ae3d27d4eb4fULL ^
                                u(k) * 0x165667b19e3779f9ULL);
  return gradients()[h % kGradients];
}

}  // namespace

double simplex_noise(double x, double y, double z) {
  constexpr double kSkew = 1.0 / 3, kUnskew = 1.0 / 6;
  const double s = (x + y + z) * kSkew;
  const auto i = static_cast<std::int64_t>(std::floor(x + s));
  const auto j = static_cast<std::int64_t>(std::floor(y + s));
  const auto k = static_cast<std::int64_t>(std::floor(z + s));
  const double t = static_cast<double>(i + j + k) * kUnskew;
  const Vec3 d0{x - (static_cast<double>(i) - t), y - (static_cast<double>(j) - t),
                z - (static_cast<double>(k) - t)};
  // The tetrahedron: the corners are visited along the axes in the order of d0's components,
  // largest first.
  const int ax = d0.x >= d0.y ? (d0.x >= d0.z ? 0 : 2) : (d0.y >= d0.z ? 1 : 2);
  const int az = d0.x < d0.y ? (d0.x < d0.z ? 0 : 2) : (d0.y < d0.z ? 1 : 2);
  std::array<int, 3> step1{}, step2{1, 1, 1};
  step1[static_cast<std::size_t>(ax)] = 1;
  step2[static_cast<std::size_t>(az)] = 0;
  const std::array<std::array<int, 3>, 4> corner{{{0, 0, 0}, step1, step2, {1, 1, 1}}};
  double n = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    const double back = static_cast<double>(c) * kUnskew;
    const Vec3 d{d0.x - corner[c][0] + back, d0.y - corner[c][1] + back,
                 d0.z - corner[c][2] + back};
    double f = 0.6 - d.x * d.x - d.y * d.y - d.z * d.z;
    if (f <= 0) continue;
    const Vec3& g = gradient(i + corner[c][0], j + corner[c][1], k + corner[c][2]);
    f *= f;
    n += f * f * (g.x * d.x + g.y * d.y + g.z * d.z);
  }
  return 32 * n;
}

}  // namespace ifsfx::flame::detail
