// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see
// flame/CMakeLists.txt; chosen at run time, ifs/cpu.h): four doubles a lane group, the same
// operations as the scalar level in the same order, so the same bits.
#include <immintrin.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "flame/detail/batch_variations.h"

namespace ifsfx::detail::kernel_avx2 {
namespace {

using V = double __attribute__((vector_size(32)));
using M = decltype(V{} < V{});
using I = std::uint64_t __attribute__((vector_size(32)));
constexpr std::size_t kW = 4;

inline V splat(double d) {
  return V{d, d, d, d};
}
inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
inline void add_to(double* p, V v) {
  store(p, load(p) + v);
}
inline V sel(M m, V a, V b) {
  return (V)(((M)a & m) | ((M)b & ~m));
}
inline bool any(M m) {
  return _mm256_movemask_pd((__m256d)m) != 0;
}
inline V vsqrt(V x) {
  return (V)_mm256_sqrt_pd((__m256d)x);
}
inline I as_bits(V v) {
  return (I)v;
}
inline V from_bits(I i) {
  return (V)i;
}
inline double lane(V v, std::size_t i) {
  return v[i];
}
inline void set_lane(V& v, std::size_t i, double d) {
  v[i] = d;
}

#include "flame/detail/vmath.inl"
// (after the functions it uses)
#include "flame/detail/batch_kernels.inl"

}  // namespace

std::span<const flame::detail::BatchVariation> flame_batch_table() {
  return kTable;
}

}  // namespace ifsfx::detail::kernel_avx2
