// SPDX-License-Identifier: Apache-2.0
// Density estimation's row of a disc on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see
// flame/CMakeLists.txt; chosen at run time, ifs/cpu.h): a bin's four channels in one register,
// each lane the scalar level's product and sum (flame/detail/density_kernel.h).
#include <immintrin.h>

#include "flame/detail/density_kernel.h"

namespace ifsfx::detail::kernel_avx2 {

void flame_spread_row(double* o, const double* w, int n, const double* v) {
  const __m256d vv = _mm256_loadu_pd(v);
  int i = 0;
  // Two taps an iteration: their loads and stores overlap (the loop is bound by them).
  for (; i + 2 <= n; i += 2) {
    const __m256d a = _mm256_loadu_pd(o + 4 * i), b = _mm256_loadu_pd(o + 4 * i + 4);
    _mm256_storeu_pd(o + 4 * i, _mm256_add_pd(a, _mm256_mul_pd(_mm256_broadcast_sd(w + i), vv)));
    _mm256_storeu_pd(o + 4 * i + 4,
                     _mm256_add_pd(b, _mm256_mul_pd(_mm256_broadcast_sd(w + i + 1), vv)));
  }
  if (i < n)
    _mm256_storeu_pd(o + 4 * i, _mm256_add_pd(_mm256_loadu_pd(o + 4 * i),
                                              _mm256_mul_pd(_mm256_broadcast_sd(w + i), vv)));
}

}  // namespace ifsfx::detail::kernel_avx2
