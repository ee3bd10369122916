// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms at the scalar level, the reference of the others: one double a
// lane (flame/detail/batch_variations.h).
#include <bit>
#include <cmath>
#include <cstdint>

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

}  // namespace ifsfx::detail::kernel_scalar
