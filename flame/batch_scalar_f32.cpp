// SPDX-License-Identifier: Apache-2.0
// The variations' float batch forms at the scalar level, the reference of the others: one float
// a lane (flame/detail/float_lanes.inl), the formulas of flame/detail/batch_kernels.inl over the
// float functions of flame/detail/vmath_f32.inl.
#include <bit>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <type_traits>

#include "flame/detail/batch_variations.h"

#define IFSFX_FLOAT_IO 1

namespace ifsfx::detail::kernel_scalar {
namespace {

using F = float;
using I = std::uint32_t;
constexpr std::size_t kW = 1;

inline F splat_f(float f) {
  return f;
}
inline F sqrt_f(F x) {
  return std::sqrt(x);
}
// (nearbyint rounds as the current mode does: to nearest, ties to even, as the AVX2 level's.)
inline F round_f(F x) {
  return std::nearbyint(x);
}
inline F floor_f(F x) {
  return std::floor(x);
}
inline F trunc_f(F x) {
  return std::trunc(x);
}
inline bool any_f(bool m) {
  return m;
}
inline F load_f(const double* p) {
  return static_cast<float>(*p);
}
inline void add_to_f(double* p, F f) {
  *p += static_cast<double>(f);
}
inline F loadu_f(const float* p) {
  return *p;
}
inline void storeu_f(float* p, F f) {
  *p = f;
}
inline I bits_f(F f) {
  return std::bit_cast<I>(f);
}
inline F floats_f(I i) {
  return std::bit_cast<F>(i);
}
inline float lane_f(F f, std::size_t) {
  return f;
}
inline void set_lane_f(F& f, std::size_t, float v) {
  f = v;
}

#include "flame/detail/float_lanes.inl"
// (after the lane type)
#include "flame/detail/vmath_f32.inl"
// (after the functions it uses)
#include "flame/detail/batch_kernels.inl"

}  // namespace

#undef IFSFX_FLOAT_IO

std::span<const flame::detail::BatchVariation> flame_batch_table_f32() {
  return kTable;
}

}  // namespace ifsfx::detail::kernel_scalar
