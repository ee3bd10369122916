// SPDX-License-Identifier: Apache-2.0
// The eight lanes of a chunk as two vectors of four doubles (AVX2 instructions): the walker of the
// AVX2 level, and of the AVX-512 level for the modes and IFSs where two independent chains of four
// lanes beat one of eight (walk_kernels_avx512.cpp). Included by those translation units inside
// their namespaces, after walk_kernels_common.inl and <immintrin.h>, like it (see there): no
// include guard, no #include, nothing of std::.
//
// It computes exactly what walk_scalar computes — same generators, same alias-table draws, same
// operation order, no fused multiply-add — so every mode gives the bytes of the scalar level. IFSs
// of up to 8 maps keep their coefficients in registers, selected per lane by permutes instead of
// gathers: walk_quads<Sink, false> for up to 4 maps, <Sink, true> for 5 to 8. The per-step helpers
// are always inlined: out of line, each step pays a call and spills its vectors to memory.

// xoshiro256+ of four lanes, word k of each lane in s_k (xoshiro_next, four at a time).
struct Lanes4 {
  __m256i s0, s1, s2, s3;

  [[gnu::always_inline]] __m256i next() {
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

Lanes4 pack_lanes4(const std::uint64_t (*rng)[4]) {
  auto word = [&](int k) {
    return _mm256_set_epi64x(static_cast<long long>(rng[3][k]), static_cast<long long>(rng[2][k]),
                             static_cast<long long>(rng[1][k]), static_cast<long long>(rng[0][k]));
  };
  return {word(0), word(1), word(2), word(3)};
}

// A coefficient of maps 0..7 in two registers (maps 0–3, 4–7).
struct Coefficient {
  __m256d lo, hi;
};

// Per-lane coefficient k[n]: a permute of 32-bit halves (2n, 2n+1) of the register holding map n;
// for IFSs of more than four maps, both registers permuted and the lane's one blended in.
template <bool kEight>
[[gnu::always_inline]] inline __m256d select_coefficient(const Coefficient& k, __m256i pair_index,
                                                         __m256d upper) {
  const __m256d lo = _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(k.lo), pair_index));
  if constexpr (!kEight) {
    return lo;
  } else {
    const __m256d hi =
        _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(k.hi), pair_index));
    return _mm256_blendv_pd(lo, hi, upper);
  }
}

struct QuadTables {
  __m256i count, threshold, alias;  // alias table of MapPicker, 32-bit entries
  __m256i palette;                  // c_n, 32-bit entries
  Coefficient a, b, c, d, e, f;
};

QuadTables load_quad_tables(const WalkSpec& w) {
  QuadTables t;
  alignas(32) std::uint32_t threshold[8] = {}, alias[8] = {}, palette[8] = {};
  for (std::uint64_t i = 0; i < w.pick_n; ++i) threshold[i] = w.threshold[i], alias[i] = w.alias[i];
  for (std::uint32_t i = 0; i < w.maps; ++i) palette[i] = w.palette[i];
  t.count = _mm256_set1_epi64x(static_cast<long long>(w.pick_n));
  t.threshold = _mm256_load_si256(reinterpret_cast<const __m256i*>(threshold));
  t.alias = _mm256_load_si256(reinterpret_cast<const __m256i*>(alias));
  t.palette = _mm256_load_si256(reinterpret_cast<const __m256i*>(palette));
  auto table = [&](const double* k) {
    alignas(32) double v[8] = {};
    for (std::uint32_t i = 0; i < w.maps; ++i) v[i] = k[i];
    return Coefficient{_mm256_load_pd(v), _mm256_load_pd(v + 4)};
  };
  t.a = table(w.a), t.b = table(w.b), t.c = table(w.c);
  t.d = table(w.d), t.e = table(w.e), t.f = table(w.f);
  return t;
}

// wrap_unit of four lanes: t − ⌊t⌋, and 0 where that is not below 1 (or is a NaN).
[[gnu::always_inline]] inline __m256d wrap_unit4(__m256d t) {
  const __m256d r = _mm256_sub_pd(t, _mm256_floor_pd(t));
  return _mm256_and_pd(r, _mm256_cmp_pd(r, _mm256_set1_pd(1.0), _CMP_LT_OQ));
}

// One chaos-game step of four lanes: the maps drawn (one per 64-bit lane, in its low half) and
// the new points (wrapped onto the torus of the tile with kWrap).
template <bool kEight, bool kWrap>
[[gnu::always_inline]] inline __m256i quad_step(const QuadTables& t, Lanes4& rng, __m256d& x,
                                                __m256d& y) {
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
  // Pair index (2n mod 8, 2n+1 mod 8) of each lane's doubles, and which register holds map n.
  const __m256i n2 = _mm256_slli_epi64(n, 1);
  const __m256i pair =
      _mm256_or_si256(n2, _mm256_slli_epi64(_mm256_add_epi64(n2, _mm256_set1_epi64x(1)), 32));
  __m256d upper = _mm256_setzero_pd();
  if constexpr (kEight) upper = _mm256_castsi256_pd(_mm256_cmpgt_epi64(n, _mm256_set1_epi64x(3)));
  // (a x + b y) + e, (c x + d y) + f: the scalar loop's order, rounded the same way.
  const __m256d nx =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(select_coefficient<kEight>(t.a, pair, upper), x),
                                  _mm256_mul_pd(select_coefficient<kEight>(t.b, pair, upper), y)),
                    select_coefficient<kEight>(t.e, pair, upper));
  const __m256d ny =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(select_coefficient<kEight>(t.c, pair, upper), x),
                                  _mm256_mul_pd(select_coefficient<kEight>(t.d, pair, upper), y)),
                    select_coefficient<kEight>(t.f, pair, upper));
  if constexpr (kWrap) {
    x = wrap_unit4(nx);
    y = wrap_unit4(ny);
  } else {
    x = nx;
    y = ny;
  }
  return n;
}

// Four lanes of a chunk and their keys and palette coordinates.
struct Quad {
  Lanes4 rng;
  __m256d x, y;
  __m256i key, colour;
};

template <class Sink, bool kEight, bool kWrap>
void walk_quads(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  const QuadTables t = load_quad_tables(w);
  std::uint64_t rng[kLanes][4];
  alignas(32) double x0[kLanes], y0[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    for (int k = 0; k < 4; ++k) rng[lane][k] = seeds.s[lane][k];
    x0[lane] = unit_interval(xoshiro_next(rng[lane]));
    y0[lane] = unit_interval(xoshiro_next(rng[lane]));
  }
  Quad q[2];
  for (int h = 0; h < 2; ++h) {
    q[h].rng = pack_lanes4(rng + 4 * h);
    q[h].x = _mm256_load_pd(x0 + 4 * h);
    q[h].y = _mm256_load_pd(y0 + 4 * h);
    q[h].key = _mm256_setzero_si256();
    q[h].colour = _mm256_setzero_si256();
  }
  // key = (key >> key_bits) | (map << (64 − key_bits)); c = (c + c_n) >> 1.
  const __m128i key_right = _mm_cvtsi32_si128(w.key_bits);
  const __m128i key_left = _mm_cvtsi32_si128(64 - w.key_bits);
  const __m256i low32 = _mm256_set1_epi64x(0xffffffff);
  auto advance = [&](Quad& l) {
    const __m256i n = quad_step<kEight, kWrap>(t, l.rng, l.x, l.y);
    if constexpr (Sink::kKeys)
      l.key = _mm256_or_si256(_mm256_srl_epi64(l.key, key_right), _mm256_sll_epi64(n, key_left));
    if constexpr (Sink::kPalette) {
      // The high half of each lane's n is 0, so the permute puts c_0 there: masked off.
      const __m256i c_n = _mm256_and_si256(_mm256_permutevar8x32_epi32(t.palette, n), low32);
      l.colour = _mm256_srli_epi64(_mm256_add_epi64(l.colour, c_n), 1);
    }
    return n;
  };
  for (int k = 0; k < w.burn_in; ++k) {
    advance(q[0]);
    advance(q[1]);
  }

  const __m256d sx = _mm256_set1_pd(w.sx), ox = _mm256_set1_pd(w.ox);
  const __m256d sy = _mm256_set1_pd(w.sy), oy = _mm256_set1_pd(w.oy);
  const __m256d width = _mm256_set1_pd(w.width), height = _mm256_set1_pd(w.height);
  const __m256d zero = _mm256_setzero_pd();
  const __m128i stride = _mm_set1_epi32(static_cast<int>(w.stride));
  // Pixel indices and maps of four lanes; plot the lanes on the raster, in lane order.
  auto emit = [&](int first_lane, int lanes_wanted, __m256i n, const Quad& l) {
    const __m256d px = _mm256_add_pd(_mm256_mul_pd(sx, l.x), ox);
    const __m256d py = _mm256_add_pd(_mm256_mul_pd(sy, l.y), oy);
    const __m256d inside = _mm256_and_pd(
        _mm256_and_pd(_mm256_cmp_pd(px, zero, _CMP_GE_OQ), _mm256_cmp_pd(px, width, _CMP_LT_OQ)),
        _mm256_and_pd(_mm256_cmp_pd(py, zero, _CMP_GE_OQ), _mm256_cmp_pd(py, height, _CMP_LT_OQ)));
    const int mask = _mm256_movemask_pd(inside) & ((1 << lanes_wanted) - 1);
    if (mask == 0) return;
    if constexpr (Sink::kQuads) {
      // MeasureSink::plot's increment of four lanes: c6 = min((c + 2^(15−b)) >> (16−b), 2^b − 1),
      // (c6 << kCountBits) | 1; the 32-bit halves of 64-bit lanes, the high ones 0 and unused.
      constexpr int kBits = MeasureCells::kPaletteBits;
      const __m256i c6 = _mm256_min_epu32(
          _mm256_srli_epi32(_mm256_add_epi32(l.colour, _mm256_set1_epi32(1 << (15 - kBits))),
                            16 - kBits),
          _mm256_set1_epi32((1 << kBits) - 1));
      const __m256i increment =
          _mm256_or_si256(_mm256_slli_epi32(c6, MeasureCells::kCountBits), _mm256_set1_epi32(1));
      const __m256i even = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
      // Lanes off the raster, or past lanes_wanted: cell 0, increment 0.
      __m128i keep =
          _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(inside), even));
      if (lanes_wanted < 4)
        keep = _mm_and_si128(
            keep, _mm_cmpgt_epi32(_mm_set1_epi32(lanes_wanted), _mm_setr_epi32(0, 1, 2, 3)));
      alignas(16) std::uint32_t cell[4], add[4];
      _mm_store_si128(
          reinterpret_cast<__m128i*>(cell),
          _mm_and_si128(keep, _mm_add_epi32(_mm_mullo_epi32(_mm256_cvttpd_epi32(py), stride),
                                            _mm256_cvttpd_epi32(px))));
      _mm_store_si128(reinterpret_cast<__m128i*>(add),
                      _mm_and_si128(keep, _mm256_castsi256_si128(
                                              _mm256_permutevar8x32_epi32(increment, even))));
      sink.plot4(cell, add);
      return;
    }
    alignas(16) std::int32_t index[4];
    alignas(32) std::uint32_t map[8];
    alignas(32) std::uint64_t key[4] = {}, colour[4] = {};
    alignas(32) double x[4] = {}, y[4] = {};
    _mm_store_si128(
        reinterpret_cast<__m128i*>(index),
        _mm_add_epi32(_mm_mullo_epi32(_mm256_cvttpd_epi32(py), stride), _mm256_cvttpd_epi32(px)));
    _mm256_store_si256(reinterpret_cast<__m256i*>(map), n);
    if constexpr (Sink::kKeys) _mm256_store_si256(reinterpret_cast<__m256i*>(key), l.key);
    if constexpr (Sink::kPalette) _mm256_store_si256(reinterpret_cast<__m256i*>(colour), l.colour);
    if constexpr (Sink::kPoints) _mm256_store_pd(x, l.x), _mm256_store_pd(y, l.y);
    for (int j = 0; j < 4; ++j)
      if (mask & (1 << j))
        sink.plot(first_lane + j, static_cast<long>(index[j]), map[2 * j], key[j],
                  static_cast<std::uint32_t>(colour[j]), x[j], y[j]);
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t k = 0; k < steps; ++k) {
    const __m256i n_lo = advance(q[0]);
    const __m256i n_hi = advance(q[1]);
    emit(0, 4, n_lo, q[0]);
    emit(4, 4, n_hi, q[1]);
  }
  const int rest = static_cast<int>(points % kLanes);
  if (rest > 0) {
    const __m256i n_lo = advance(q[0]);
    const __m256i n_hi = advance(q[1]);
    emit(0, rest < 4 ? rest : 4, n_lo, q[0]);
    if (rest > 4) emit(4, rest - 4, n_hi, q[1]);
  }
}
