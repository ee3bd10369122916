// The renderers' hot loop on AVX2: the eight walkers of a chunk as two vectors of four doubles.
// It computes exactly what plot_chunk_scalar (walkers.h) computes — same generators, same
// alias-table draws, same operation order, no fused multiply-add — so the two give identical
// pixels and the scalar loop serves as its reference in the tests. Used for IFSs of at most four
// maps, whose coefficients fit one register and are selected per lane by a permute instead of a
// gather.
#pragma once

#ifdef __AVX2__
#include <immintrin.h>

#include "ifs/detail/walkers.h"

namespace ifsfx::detail {

inline constexpr std::size_t kAvx2MaxMaps = 4;

namespace avx2 {

struct Lanes4 {
  __m256i s0, s1, s2, s3;  // xoshiro256+ state of four lanes, word k of each lane in s_k

  __m256i next() {
    const __m256i result = _mm256_add_epi64(s0, s3);
    const __m256i t = _mm256_slli_epi64(s1, 17);
    s2 = _mm256_xor_si256(s2, s0);
    s3 = _mm256_xor_si256(s3, s1);
    s1 = _mm256_xor_si256(s1, s2);
    s0 = _mm256_xor_si256(s0, s3);
    s2 = _mm256_xor_si256(s2, t);
    s3 = _mm256_or_si256(_mm256_slli_epi64(s3, 45), _mm256_srli_epi64(s3, 19));
    return result;
  }
};

inline Lanes4 pack(const LaneRng* rng) {
  auto word = [&](int k) {
    return _mm256_set_epi64x(
        static_cast<long long>(rng[3].s[k]), static_cast<long long>(rng[2].s[k]),
        static_cast<long long>(rng[1].s[k]), static_cast<long long>(rng[0].s[k]));
  };
  return {word(0), word(1), word(2), word(3)};
}

// Per-lane coefficient k[n] for n < 4: a permute of 32-bit halves (2n, 2n+1).
inline __m256d select(__m256d table, __m256i pair_index) {
  return _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(table), pair_index));
}

struct Tables {
  __m256i count, threshold, alias;  // alias table of MapPicker, 32-bit entries
  __m256d a, b, c, d, e, f;
};

// One chaos-game step of four lanes: the maps drawn (one per 64-bit lane, in its low half) and
// the new points.
inline __m256i step(const Tables& t, Lanes4& rng, __m256d& x, __m256d& y) {
  const __m256i r = rng.next();
  // column = ((r >> 32) · N) >> 32; map = low32(r) < threshold[column] ? column : alias[column]
  const __m256i column = _mm256_srli_epi64(_mm256_mul_epu32(_mm256_srli_epi64(r, 32), t.count), 32);
  const __m256i threshold = _mm256_permutevar8x32_epi32(t.threshold, column);
  const __m256i alias = _mm256_permutevar8x32_epi32(t.alias, column);
  const __m256i bias = _mm256_set1_epi32(static_cast<int>(0x80000000u));
  const __m256i below =
      _mm256_cmpgt_epi32(_mm256_xor_si256(threshold, bias), _mm256_xor_si256(r, bias));
  const __m256i n =
      _mm256_and_si256(_mm256_blendv_epi8(alias, column, below), _mm256_set1_epi64x(0xffffffff));
  const __m256i n2 = _mm256_slli_epi64(n, 1);
  const __m256i pair =
      _mm256_or_si256(n2, _mm256_slli_epi64(_mm256_add_epi64(n2, _mm256_set1_epi64x(1)), 32));
  // (a x + b y) + e, (c x + d y) + f: the scalar loop's order, rounded the same way.
  const __m256d nx = _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(select(t.a, pair), x), _mm256_mul_pd(select(t.b, pair), y)),
      select(t.e, pair));
  const __m256d ny = _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(select(t.c, pair), x), _mm256_mul_pd(select(t.d, pair), y)),
      select(t.f, pair));
  x = nx;
  y = ny;
  return n;
}

}  // namespace avx2

// walk_chunk_scalar on AVX2, for IFSs of at most kAvx2MaxMaps maps.
template <bool kKeys, bool kPalette = false, class Plot>
void walk_chunk_avx2(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                     std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                     int key_bits, const std::uint32_t* palette, Plot&& plot) {
  avx2::Tables t;
  __m256i colour_table = _mm256_setzero_si256();  // c_n of maps 0..3, 32-bit entries
  if constexpr (kPalette) {
    alignas(32) std::uint32_t c[8] = {};
    for (std::size_t i = 0; i < maps.a.size(); ++i) c[i] = palette[i];
    colour_table = _mm256_load_si256(reinterpret_cast<const __m256i*>(c));
  }
  {
    const MapPicker::View pick = picker.view();
    alignas(32) std::uint32_t threshold[8] = {}, alias[8] = {};
    for (std::uint64_t i = 0; i < pick.n; ++i)
      threshold[i] = pick.threshold[i], alias[i] = pick.alias[i];
    t.count = _mm256_set1_epi64x(static_cast<long long>(pick.n));
    t.threshold = _mm256_load_si256(reinterpret_cast<const __m256i*>(threshold));
    t.alias = _mm256_load_si256(reinterpret_cast<const __m256i*>(alias));
    auto table = [&](const std::vector<double>& k) {
      alignas(32) double v[4] = {};
      for (std::size_t i = 0; i < k.size(); ++i) v[i] = k[i];
      return _mm256_load_pd(v);
    };
    t.a = table(maps.a), t.b = table(maps.b), t.c = table(maps.c);
    t.d = table(maps.d), t.e = table(maps.e), t.f = table(maps.f);
  }
  LaneRng lanes[kLanes];
  alignas(32) double x0[kLanes], y0[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    lanes[lane].seed(seed, chunk, lane);
    x0[lane] = start_coordinate(lanes[lane]);
    y0[lane] = start_coordinate(lanes[lane]);
  }
  avx2::Lanes4 rng_lo = avx2::pack(lanes), rng_hi = avx2::pack(lanes + 4);
  __m256d x_lo = _mm256_load_pd(x0), x_hi = _mm256_load_pd(x0 + 4);
  __m256d y_lo = _mm256_load_pd(y0), y_hi = _mm256_load_pd(y0 + 4);
  // Address keys (kKeys): key = (key >> key_bits) | (map << (64 - key_bits)) per step; with
  // kPalette the same registers carry the palette coordinates, c = (c + c_n) >> 1 per step.
  __m256i key_lo = _mm256_setzero_si256(), key_hi = _mm256_setzero_si256();
  const __m128i key_right = _mm_cvtsi32_si128(key_bits);
  const __m128i key_left = _mm_cvtsi32_si128(64 - key_bits);
  const __m256i low32 = _mm256_set1_epi64x(0xffffffff);
  auto advance = [&](avx2::Lanes4& rng, __m256d& x, __m256d& y, __m256i& key) {
    const __m256i n = avx2::step(t, rng, x, y);
    if constexpr (kKeys)
      key = _mm256_or_si256(_mm256_srl_epi64(key, key_right), _mm256_sll_epi64(n, key_left));
    if constexpr (kPalette) {
      // The high half of each lane's n is 0, so the permute puts c_0 there: masked off.
      const __m256i c_n = _mm256_and_si256(_mm256_permutevar8x32_epi32(colour_table, n), low32);
      key = _mm256_srli_epi64(_mm256_add_epi64(key, c_n), 1);
    }
    return n;
  };
  for (int k = 0; k < burn_in; ++k) {
    advance(rng_lo, x_lo, y_lo, key_lo);
    advance(rng_hi, x_hi, y_hi, key_hi);
  }

  const __m256d sx = _mm256_set1_pd(mapping.sx), ox = _mm256_set1_pd(mapping.ox);
  const __m256d sy = _mm256_set1_pd(mapping.sy), oy = _mm256_set1_pd(mapping.oy);
  const __m256d width = _mm256_set1_pd(mapping.width), height = _mm256_set1_pd(mapping.height);
  const __m256d zero = _mm256_setzero_pd();
  const __m128i stride = _mm_set1_epi32(static_cast<int>(mapping.stride));
  // Pixel indices and maps of four lanes; plot() the lanes on the raster, in lane order.
  auto emit = [&](int first_lane, int lanes_wanted, __m256i n, __m256d px_x, __m256d px_y,
                  __m256i key) {
    const __m256d px = _mm256_add_pd(_mm256_mul_pd(sx, px_x), ox);
    const __m256d py = _mm256_add_pd(_mm256_mul_pd(sy, px_y), oy);
    const __m256d inside = _mm256_and_pd(
        _mm256_and_pd(_mm256_cmp_pd(px, zero, _CMP_GE_OQ), _mm256_cmp_pd(px, width, _CMP_LT_OQ)),
        _mm256_and_pd(_mm256_cmp_pd(py, zero, _CMP_GE_OQ), _mm256_cmp_pd(py, height, _CMP_LT_OQ)));
    int mask = _mm256_movemask_pd(inside) & ((1 << lanes_wanted) - 1);
    if (mask == 0) return;
    alignas(16) std::int32_t index[4];
    alignas(32) std::uint32_t map[8];
    _mm_store_si128(
        reinterpret_cast<__m128i*>(index),
        _mm_add_epi32(_mm_mullo_epi32(_mm256_cvttpd_epi32(py), stride), _mm256_cvttpd_epi32(px)));
    _mm256_store_si256(reinterpret_cast<__m256i*>(map), n);
    if constexpr (kKeys || kPalette) {
      alignas(32) std::uint64_t keys[4];
      _mm256_store_si256(reinterpret_cast<__m256i*>(keys), key);
      for (int j = 0; j < 4; ++j)
        if (mask & (1 << j)) {
          if constexpr (kKeys)
            plot(first_lane + j, static_cast<long>(index[j]), map[2 * j], keys[j]);
          else
            plot(first_lane + j, static_cast<long>(index[j]), map[2 * j],
                 static_cast<std::uint32_t>(keys[j]));
        }
    } else {
      for (int j = 0; j < 4; ++j)
        if (mask & (1 << j)) plot(first_lane + j, static_cast<long>(index[j]), map[2 * j]);
    }
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t k = 0; k < steps; ++k) {
    const __m256i n_lo = advance(rng_lo, x_lo, y_lo, key_lo);
    const __m256i n_hi = advance(rng_hi, x_hi, y_hi, key_hi);
    emit(0, 4, n_lo, x_lo, y_lo, key_lo);
    emit(4, 4, n_hi, x_hi, y_hi, key_hi);
  }
  const int rest = static_cast<int>(points % kLanes);
  if (rest > 0) {
    const __m256i n_lo = advance(rng_lo, x_lo, y_lo, key_lo);
    const __m256i n_hi = advance(rng_hi, x_hi, y_hi, key_hi);
    emit(0, std::min(rest, 4), n_lo, x_lo, y_lo, key_lo);
    if (rest > 4) emit(4, rest - 4, n_hi, x_hi, y_hi, key_hi);
  }
}

// plot_chunk_scalar on AVX2, for IFSs of at most kAvx2MaxMaps maps.
template <class Plot>
void plot_chunk_avx2(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                     std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                     Plot&& plot) {
  walk_chunk_avx2<false>(maps, picker, mapping, seed, chunk, points, burn_in, 0, nullptr, plot);
}

}  // namespace ifsfx::detail
#endif  // __AVX2__
