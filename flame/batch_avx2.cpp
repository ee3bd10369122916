// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see
// flame/CMakeLists.txt; chosen at run time, ifs/cpu.h): four doubles a lane group, the same
// operations as the scalar level in the same order, so the same bits.
#include <immintrin.h>

#include <algorithm>
#include <array>
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

namespace {
// For each 8-bit mask, the indices of its set bits packed to the low bytes (a vpermd order).
constexpr auto kPack = [] {
  std::array<std::uint64_t, 256> t{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    unsigned n = 0;
    for (unsigned b = 0; b < 8; ++b)
      if ((mask >> b & 1) != 0) t[mask] |= std::uint64_t{b} << (8 * n++);
  }
  return t;
}();

// Walkers i … i + 7 whose bits of `mask` are set (those below m), packed to the front by a
// permutation and stored at out (the other lanes' entries are written over next); how many.
inline std::size_t append_walkers(unsigned mask, std::size_t i, std::size_t m, std::uint32_t* out) {
  if (m - i < 8) mask &= (1u << (m - i)) - 1;
  const __m256i perm = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(kPack[mask])));
  const __m256i walkers = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(i)),
                                           _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm256_permutevar8x32_epi32(walkers, perm));
  return static_cast<std::size_t>(__builtin_popcount(mask));
}
}  // namespace

// The scalar level's listing eight walkers at a time: the lanes that picked xform j appended
// in order (append_walkers), so the same order.
void flame_list_by_xform(const std::uint32_t* k, std::size_t m, std::size_t steps,
                         std::uint32_t* order, std::size_t* first) {
  std::size_t c = 0;
  for (std::size_t j = 0; j < steps; ++j) {
    first[j] = c;
    const __m256i want = _mm256_set1_epi32(static_cast<int>(j));
    for (std::size_t i = 0; i < m; i += 8) {
      const __m256i kk = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k + i));
      const auto mask = static_cast<unsigned>(
          _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(kk, want))));
      c += append_walkers(mask, i, m, order + c);
    }
  }
  first[steps] = c;
}

// The scalar level's list of the walkers to plot eight at a time: the lanes with a bin appended
// in order (append_walkers), so the same list.
std::size_t flame_hits(const std::uint32_t* at, std::size_t m, std::uint32_t* hits) {
  const __m256i off = _mm256_set1_epi32(-1);  // kOffBin
  std::size_t n = 0;
  for (std::size_t i = 0; i < m; i += 8) {
    const __m256i bins = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(at + i));
    const auto mask = ~static_cast<unsigned>(
                          _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(bins, off)))) &
                      0xFFu;
    n += append_walkers(mask, i, m, hits + n);
  }
  return n;
}

// The scalar level's flame_bin_numbers four points at a time: the same products and sums in
// the same order (no FMA), exact comparisons and truncations, so the same numbers.
std::size_t flame_bin_numbers(const flame::detail::BinGrid& g, std::size_t n, const double* x,
                              const double* y, std::uint32_t* at) {
  const AffineMap& m = g.to_bins;
  const __m256d a = _mm256_set1_pd(m.a), b = _mm256_set1_pd(m.b), c = _mm256_set1_pd(m.c);
  const __m256d d = _mm256_set1_pd(m.d), e = _mm256_set1_pd(m.e), f = _mm256_set1_pd(m.f);
  const __m256d zero = _mm256_setzero_pd(), sign = _mm256_set1_pd(-0.0);
  const __m256d esc = _mm256_set1_pd(flame::detail::kEscape);
  const __m256d bx_max = _mm256_set1_pd(g.bins_x), by_max = _mm256_set1_pd(g.bins_y);
  const __m128i row = _mm_set1_epi32(static_cast<int>(g.bins_x));
  const __m128i off = _mm_set1_epi32(-1);
  // The low halves of the four 64-bit masks, as four 32-bit masks.
  const __m256i halves = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
  std::size_t escaped = 0;
  for (std::size_t i = 0; i < n; i += 4) {
    const __m256d px = _mm256_loadu_pd(x + i), py = _mm256_loadu_pd(y + i);
    const __m256d inside =
        _mm256_and_pd(_mm256_cmp_pd(_mm256_andnot_pd(sign, px), esc, _CMP_LT_OQ),
                      _mm256_cmp_pd(_mm256_andnot_pd(sign, py), esc, _CMP_LT_OQ));
    const __m256d bx = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(a, px), _mm256_mul_pd(b, py)), e);
    const __m256d by = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(c, px), _mm256_mul_pd(d, py)), f);
    __m256d in = _mm256_and_pd(inside, _mm256_cmp_pd(bx, zero, _CMP_GE_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(bx, bx_max, _CMP_LT_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(by, zero, _CMP_GE_OQ));
    in = _mm256_and_pd(in, _mm256_cmp_pd(by, by_max, _CMP_LT_OQ));
    const int lanes = static_cast<int>(std::min<std::size_t>(4, n - i));
    // The count of the escaped lanes' bits from a table of 4-bit counts (no POPCNT needed).
    const unsigned gone = static_cast<unsigned>(~_mm256_movemask_pd(inside)) & ((1u << lanes) - 1);
    escaped += (0x4332322132212110ULL >> (4 * gone)) & 0xF;
    // In range the truncation is the scalar cast's; out of range its value is never used.
    const __m128i ix = _mm256_cvttpd_epi32(bx), iy = _mm256_cvttpd_epi32(by);
    const __m128i bin = _mm_add_epi32(_mm_mullo_epi32(iy, row), ix);
    const __m128i keep =
        _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(in), halves));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at + i), _mm_blendv_epi8(off, bin, keep));
  }
  return escaped;
}

namespace {
using U4 = std::uint32_t __attribute__((vector_size(16)));
using M4 = std::int32_t __attribute__((vector_size(16)));  // a comparison's lanes
inline unsigned wrapped_lanes(M4 m) {
  return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps((__m128i)m)));
}

}  // namespace

#include "flame/detail/plot_kernel.inl"

}  // namespace ifsfx::detail::kernel_avx2
