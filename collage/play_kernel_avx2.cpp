// SPDX-License-Identifier: Apache-2.0
// The attractor loss's chaos game on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see
// collage/CMakeLists.txt; chosen at run time, ifs/cpu.h): the eight lanes of the scalar reference
// (collage/detail/play_kernel.h) in one register, each lane the scalar's operations in its order.
// The maps' coefficients are picked by VPERMPS for N ≤ 8 and gathered above; the distance map's
// four corners come from the cell table, one load a lane. Nothing from the standard library: see
// play_kernel.h.
#include <immintrin.h>

#include "collage/detail/play_kernel.h"

namespace ifsfx::detail::kernel_avx2 {

namespace {

// The eight chains (lanes) and the maps' coefficients.
struct Chains {
  __m256 x, y;
  __m256 row[6];  // the rows a .. f of the maps' coefficients (N ≤ 8)
  const float* coefficients;
  int stride;
  const float* cumulative;
  int count;
};

// Steps t0 .. t1 − 1 of the chains; with `px`, each step's pixel points stored there (8 a step).
// Count: N when N ≤ 8, the compares unrolled and the coefficients picked by VPERMPS; 0 for any
// N, gathered. The map index of a lane is the count of the N − 1 thresholds at or below its draw
// (a true compare is all ones, −1 as an integer).
template <int Count>
void advance(Chains& c, const float* draws, std::size_t t0, std::size_t t1, float* px, float* py,
             float size, float pad) {
  const int thresholds = Count > 0 ? Count - 1 : c.count - 1;
  const __m256 one = _mm256_set1_ps(1.0f), s = _mm256_set1_ps(size), o = _mm256_set1_ps(pad);
  __m256 x = c.x, y = c.y;
  for (std::size_t t = t0; t < t1; ++t) {
    const __m256 u = _mm256_loadu_ps(draws + 8 * t);
    __m256i n = _mm256_setzero_si256();
    for (int k = 0; k < thresholds; ++k) {
      const __m256 ge = _mm256_cmp_ps(u, _mm256_broadcast_ss(c.cumulative + k), _CMP_GE_OQ);
      n = _mm256_sub_epi32(n, _mm256_castps_si256(ge));
    }
    __m256 m[6];
    for (int k = 0; k < 6; ++k)
      m[k] = Count > 0 ? _mm256_permutevar8x32_ps(c.row[k], n)
                       : _mm256_i32gather_ps(c.coefficients + k * c.stride, n, 4);
    const __m256 x1 =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(m[0], x), _mm256_mul_ps(m[1], y)), m[4]);
    y = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(m[2], x), _mm256_mul_ps(m[3], y)), m[5]);
    x = x1;
    if (px) {
      _mm256_store_ps(px + 8 * (t - t0), _mm256_add_ps(_mm256_mul_ps(x, s), o));
      _mm256_store_ps(py + 8 * (t - t0), _mm256_add_ps(_mm256_mul_ps(_mm256_sub_ps(one, y), s), o));
    }
  }
  c.x = x;
  c.y = y;
}

using Advance = void (*)(Chains&, const float*, std::size_t, std::size_t, float*, float*, float,
                         float);

// The steps for N maps: advance<N> up to 8, the gathered form advance<0> above (and at entry 0,
// which N ≥ 1 never asks for).
Advance advance_for(int count) {
  static constexpr Advance kByCount[] = {advance<0>, advance<1>, advance<2>, advance<3>, advance<4>,
                                         advance<5>, advance<6>, advance<7>, advance<8>};
  return count >= 0 && count <= 8 ? kByCount[count] : advance<0>;
}

// The distance map's bilinear value at canvas points (px, py), as the scalar lookup.
__m256 lookup(const float* cells, int side, __m256 px, __m256 py) {
  const __m256 half = _mm256_set1_ps(0.5f), zero = _mm256_setzero_ps();
  const __m256 hi = _mm256_set1_ps(static_cast<float>(side - 1));
  const __m256i last = _mm256_set1_epi32(side - 2);
  const __m256 u = _mm256_sub_ps(px, half), v = _mm256_sub_ps(py, half);
  const __m256 cu = _mm256_min_ps(_mm256_max_ps(u, zero), hi);
  const __m256 cv = _mm256_min_ps(_mm256_max_ps(v, zero), hi);
  const __m256 du = _mm256_sub_ps(u, cu), dv = _mm256_sub_ps(v, cv);
  const __m256 out = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(du, du), _mm256_mul_ps(dv, dv)));
  const __m256i c0 = _mm256_min_epi32(_mm256_cvttps_epi32(cu), last);
  const __m256i r0 = _mm256_min_epi32(_mm256_cvttps_epi32(cv), last);
  const __m256 c0f = _mm256_cvtepi32_ps(c0), r0f = _mm256_cvtepi32_ps(r0);
  const __m256 fu = _mm256_sub_ps(cu, c0f), fv = _mm256_sub_ps(cv, r0f);
  alignas(32) int at[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(at),
                     _mm256_add_epi32(_mm256_mullo_epi32(r0, _mm256_set1_epi32(side)), c0));
  // Each lane's cell is one 16-byte load (d₀₀, d₀₁, d₁₀, d₁₁); four 4 × 4 transposes, two at a
  // time, make the corners' registers. (Eight loads and eight shuffles: cheaper than four
  // gathers, which are microcoded on AMD's Zen.)
  const auto cell = [&](int lane) { return _mm_loadu_ps(cells + 4 * at[lane]); };
  const __m256 q0 = _mm256_insertf128_ps(_mm256_castps128_ps256(cell(0)), cell(4), 1);
  const __m256 q1 = _mm256_insertf128_ps(_mm256_castps128_ps256(cell(1)), cell(5), 1);
  const __m256 q2 = _mm256_insertf128_ps(_mm256_castps128_ps256(cell(2)), cell(6), 1);
  const __m256 q3 = _mm256_insertf128_ps(_mm256_castps128_ps256(cell(3)), cell(7), 1);
  const __m256 t0 = _mm256_unpacklo_ps(q0, q1), t1 = _mm256_unpackhi_ps(q0, q1);
  const __m256 t2 = _mm256_unpacklo_ps(q2, q3), t3 = _mm256_unpackhi_ps(q2, q3);
  const __m256 d00 = _mm256_shuffle_ps(t0, t2, 0x44), d01 = _mm256_shuffle_ps(t0, t2, 0xee);
  const __m256 d10 = _mm256_shuffle_ps(t1, t3, 0x44), d11 = _mm256_shuffle_ps(t1, t3, 0xee);
  const __m256 top = _mm256_add_ps(d00, _mm256_mul_ps(fu, _mm256_sub_ps(d01, d00)));
  const __m256 bottom = _mm256_add_ps(d10, _mm256_mul_ps(fu, _mm256_sub_ps(d11, d10)));
  return _mm256_add_ps(_mm256_add_ps(top, _mm256_mul_ps(fv, _mm256_sub_ps(bottom, top))), out);
}

// Marks the pixels of the lanes whose point lies on the canvas; the others mark the sink byte
// past the canvas (no branch: a point leaves the canvas at random).
void mark(std::uint8_t* hits, int side, __m256 px, __m256 py) {
  const __m256 zero = _mm256_setzero_ps(), far = _mm256_set1_ps(static_cast<float>(side));
  const __m256 on = _mm256_and_ps(
      _mm256_and_ps(_mm256_cmp_ps(px, zero, _CMP_GE_OQ), _mm256_cmp_ps(py, zero, _CMP_GE_OQ)),
      _mm256_and_ps(_mm256_cmp_ps(px, far, _CMP_LT_OQ), _mm256_cmp_ps(py, far, _CMP_LT_OQ)));
  const __m256i pixel =
      _mm256_add_epi32(_mm256_mullo_epi32(_mm256_cvttps_epi32(py), _mm256_set1_epi32(side)),
                       _mm256_cvttps_epi32(px));
  alignas(32) int at[8];
  _mm256_store_si256(
      reinterpret_cast<__m256i*>(at),
      _mm256_blendv_epi8(_mm256_set1_epi32(side * side), pixel, _mm256_castps_si256(on)));
  for (int lane = 0; lane < 8; ++lane) hits[at[lane]] = 1;
}

}  // namespace

double collage_play(const collage::detail::PlayInput& in) {
  // In blocks of steps: first the chains, their pixel points stored, then the look-ups and marks
  // of the block, so that each loop keeps its values in registers. (The inputs are read into
  // locals: a byte store to `hits` may alias anything, and would make the compiler reload them.)
  constexpr std::size_t block = 32;
  const std::size_t steps = in.steps, burn_in = in.burn_in < steps ? in.burn_in : steps;
  const int side = in.side;
  const float* const cells = in.cells;
  std::uint8_t* const hits = in.hits;
  Chains chains{_mm256_set1_ps(0.5f),
                _mm256_set1_ps(0.5f),
                {},
                in.coefficients,
                in.stride,
                in.cumulative,
                in.count};
  if (in.count <= 8)
    for (int k = 0; k < 6; ++k) chains.row[k] = _mm256_loadu_ps(in.coefficients + k * in.stride);
  const Advance step = advance_for(in.count);
  step(chains, in.draws, 0, burn_in, nullptr, nullptr, in.size, in.pad);
  __m256d low = _mm256_setzero_pd(), high = low;
  alignas(32) float px[8 * block], py[8 * block];
  for (std::size_t begin = burn_in; begin < steps; begin += block) {
    const std::size_t span = steps - begin < block ? steps - begin : block;
    step(chains, in.draws, begin, begin + span, px, py, in.size, in.pad);
    for (std::size_t j = 0; j < span; ++j) {
      const __m256 qx = _mm256_load_ps(px + 8 * j), qy = _mm256_load_ps(py + 8 * j);
      const __m256 value = lookup(cells, side, qx, qy);
      low = _mm256_add_pd(low, _mm256_cvtps_pd(_mm256_castps256_ps128(value)));
      high = _mm256_add_pd(high, _mm256_cvtps_pd(_mm256_extractf128_ps(value, 1)));
      if (hits) mark(hits, side, qx, qy);
    }
  }
  alignas(32) double spill[8];
  _mm256_store_pd(spill, low);
  _mm256_store_pd(spill + 4, high);
  double total = 0;
  for (int lane = 0; lane < 8; ++lane) total += spill[lane];
  return total;
}

}  // namespace ifsfx::detail::kernel_avx2
