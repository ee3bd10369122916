// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms at the scalar level, the reference of the others: one double a
// lane (flame/detail/batch_variations.h).
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "flame/detail/batch_variations.h"

namespace ifsfx::detail::kernel_scalar {
namespace {

using V = double;
using M = bool;
using I = std::uint64_t;
constexpr std::size_t kW = 1;

inline V splat(double d) {
  return d;
}
inline V load(const double* p) {
  return *p;
}
inline void store(double* p, V v) {
  *p = v;
}
inline void add_to(double* p, V v) {
  store(p, load(p) + v);
}
inline V sel(M m, V a, V b) {
  return m ? a : b;
}
inline bool any(M m) {
  return m;
}
inline V vsqrt(V x) {
  return std::sqrt(x);
}
inline I as_bits(V v) {
  return std::bit_cast<I>(v);
}
inline V from_bits(I i) {
  return std::bit_cast<V>(i);
}
inline double lane(V v, std::size_t) {
  return v;
}
inline void set_lane(V& v, std::size_t, double d) {
  v = d;
}

#include "flame/detail/vmath.inl"
// (after the functions it uses)
#include "flame/detail/batch_kernels.inl"

}  // namespace

std::span<const flame::detail::BatchVariation> flame_batch_table() {
  return kTable;
}

// The reference listing: each xform's walkers in ascending order, branch-free (the store is
// always made, the count moves on where the walker picked the xform).
void flame_list_by_xform(const std::uint32_t* k, std::size_t m, std::size_t steps,
                         std::uint32_t* order, std::size_t* first) {
  std::size_t c = 0;
  for (std::size_t j = 0; j < steps; ++j) {
    first[j] = c;
    for (std::size_t i = 0; i < m; ++i) {
      order[c] = static_cast<std::uint32_t>(i);
      c += k[i] == j ? 1 : 0;
    }
  }
  first[steps] = c;
}

// The reference list of the walkers to plot: the store is always made, the count moves on
// where the walker has a bin.
std::size_t flame_hits(const std::uint32_t* at, std::size_t m, std::uint32_t* hits) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < m; ++i) {
    hits[n] = static_cast<std::uint32_t>(i);
    n += at[i] != flame::detail::kOffBin ? 1 : 0;
  }
  return n;
}

// The reference of every level's bin numbering: AffineMap's operations in its order, the
// comparisons and truncations exact.
std::size_t flame_bin_numbers(const flame::detail::BinGrid& g, std::size_t n, const double* x,
                              const double* y, std::uint32_t* at) {
  const AffineMap& m = g.to_bins;
  const double bx_max = g.bins_x, by_max = g.bins_y;
  std::size_t escaped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool out =
        !(std::abs(x[i]) < flame::detail::kEscape && std::abs(y[i]) < flame::detail::kEscape);
    const double bx = m.a * x[i] + m.b * y[i] + m.e;
    const double by = m.c * x[i] + m.d * y[i] + m.f;
    const bool in = !out && bx >= 0 && bx < bx_max && by >= 0 && by < by_max;
    escaped += out;
    at[i] = in ? static_cast<std::uint32_t>(by) * g.bins_x + static_cast<std::uint32_t>(bx)
               : flame::detail::kOffBin;
  }
  return escaped;
}

namespace {
using U4 = std::uint32_t __attribute__((vector_size(16)));
using M4 = std::int32_t __attribute__((vector_size(16)));  // a comparison's lanes
inline unsigned wrapped_lanes(M4 m) {
  return (m[0] != 0 ? 1u : 0u) | (m[1] != 0 ? 2u : 0u) | (m[2] != 0 ? 4u : 0u) |
         (m[3] != 0 ? 8u : 0u);
}

}  // namespace

#include "flame/detail/plot_kernel.inl"

}  // namespace ifsfx::detail::kernel_scalar
