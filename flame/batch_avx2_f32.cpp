// SPDX-License-Identifier: Apache-2.0
// The variations' float batch forms on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see
// flame/CMakeLists.txt; chosen at run time, ifs/cpu.h): eight floats a lane group, the same
// operations as the scalar level's float forms in the same order, so the same bits.
#include <immintrin.h>

#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "flame/detail/batch_variations.h"

#define IFSFX_FLOAT_IO 1

namespace ifsfx::detail::kernel_avx2 {
namespace {

using F = float __attribute__((vector_size(32)));
using I = std::uint32_t __attribute__((vector_size(32)));
constexpr std::size_t kW = 8;

inline F splat_f(float f) {
  return F{f, f, f, f, f, f, f, f};
}
inline F sqrt_f(F x) {
  return (F)_mm256_sqrt_ps((__m256)x);
}
inline F round_f(F x) {
  return (F)_mm256_round_ps((__m256)x, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}
inline F floor_f(F x) {
  return (F)_mm256_round_ps((__m256)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
inline F trunc_f(F x) {
  return (F)_mm256_round_ps((__m256)x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
}
inline bool any_f(decltype(F{} < F{}) m) {
  return _mm256_movemask_ps((__m256)m) != 0;
}
// Eight doubles rounded to floats (vcvtpd2ps, to nearest, as the scalar level's cast; written
// with intrinsics: GCC lowers a 64-byte __builtin_convertvector to scalar conversions).
inline F load_f(const double* p) {
  const __m128 lo = _mm256_cvtpd_ps(_mm256_loadu_pd(p));
  const __m128 hi = _mm256_cvtpd_ps(_mm256_loadu_pd(p + 4));
  return (F)_mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}
inline void add_to_f(double* p, F f) {
  const __m256 v = (__m256)f;
  _mm256_storeu_pd(p,
                   _mm256_add_pd(_mm256_loadu_pd(p), _mm256_cvtps_pd(_mm256_castps256_ps128(v))));
  _mm256_storeu_pd(
      p + 4, _mm256_add_pd(_mm256_loadu_pd(p + 4), _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1))));
}
inline F loadu_f(const float* p) {
  return (F)_mm256_loadu_ps(p);
}
inline void storeu_f(float* p, F f) {
  _mm256_storeu_ps(p, (__m256)f);
}
inline I bits_f(F f) {
  return (I)f;
}
inline F floats_f(I i) {
  return (F)i;
}
inline float lane_f(F f, std::size_t i) {
  return f[i];
}
inline void set_lane_f(F& f, std::size_t i, float v) {
  f[i] = v;
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

}  // namespace ifsfx::detail::kernel_avx2
