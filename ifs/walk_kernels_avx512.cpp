// SPDX-License-Identifier: Apache-2.0
// The chaos-game kernels on AVX-512 (compiled with -march=x86-64-v4 -mno-fma, see
// ifs/CMakeLists.txt; chosen at run time, ifs/cpu.h): the eight lanes of a chunk in one vector of
// eight doubles (or, where that pays less, as two vectors of four: walk_quads.inl, see walk()).
// They compute exactly what walk_scalar computes — same generators, same alias-table draws, same
// operation order, no fused multiply-add — so every mode gives the bytes of the scalar level. IFSs
// of up to 16 maps keep their coefficients in registers (one for 8 maps, two for 16), selected per
// lane by a permute; larger ones run walk_scalar, compiled here for this instruction set. GCC 12's
// AVX-512 headers initialise their "undefined" vectors from themselves, which -O3 reports as used
// uninitialised where they are inlined (GCC bug 105593): not a fault of this file.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if defined(__GNUC__) && !defined(__clang__)  // clang has no such warning group
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#pragma GCC diagnostic pop

#include "ifs/detail/walk_kernels.h"

namespace ifsfx::detail::kernel_avx512 {
namespace {

#include "ifs/detail/walk_kernels_common.inl"

constexpr CpuLevel kLevel = CpuLevel::avx512;

#include "ifs/detail/walk_quads.inl"

// A table of 16 64-bit entries (maps 0–7, 8–15), indexed per lane.
struct Table {
  __m512i lo, hi;
};
struct TablePd {
  __m512d lo, hi;
};

template <bool kSixteen>
[[gnu::always_inline]] inline __m512i lookup(const Table& t, __m512i index) {
  if constexpr (kSixteen)
    return _mm512_permutex2var_epi64(t.lo, index, t.hi);
  else
    return _mm512_permutexvar_epi64(index, t.lo);
}

template <bool kSixteen>
[[gnu::always_inline]] inline __m512d lookup(const TablePd& t, __m512i index) {
  if constexpr (kSixteen)
    return _mm512_permutex2var_pd(t.lo, index, t.hi);
  else
    return _mm512_permutexvar_pd(index, t.lo);
}

struct OctoTables {
  __m512i count;
  Table threshold, alias, palette;  // alias table of MapPicker and c_n, zero-extended
  TablePd a, b, c, d, e, f;
};

OctoTables load_octo_tables(const WalkSpec& w) {
  OctoTables t;
  alignas(64) std::uint64_t threshold[16] = {}, alias[16] = {}, palette[16] = {};
  for (std::uint64_t i = 0; i < w.pick_n; ++i) threshold[i] = w.threshold[i], alias[i] = w.alias[i];
  for (std::uint32_t i = 0; i < w.maps; ++i) palette[i] = w.palette[i];
  auto table = [](const std::uint64_t* v) {
    return Table{_mm512_load_si512(v), _mm512_load_si512(v + 8)};
  };
  t.count = _mm512_set1_epi64(static_cast<long long>(w.pick_n));
  t.threshold = table(threshold);
  t.alias = table(alias);
  t.palette = table(palette);
  auto coefficient = [&](const double* k) {
    alignas(64) double v[16] = {};
    for (std::uint32_t i = 0; i < w.maps; ++i) v[i] = k[i];
    return TablePd{_mm512_load_pd(v), _mm512_load_pd(v + 8)};
  };
  t.a = coefficient(w.a), t.b = coefficient(w.b), t.c = coefficient(w.c);
  t.d = coefficient(w.d), t.e = coefficient(w.e), t.f = coefficient(w.f);
  return t;
}

// xoshiro256+ of eight lanes, word k of each lane in s_k (xoshiro_next, eight at a time).
struct Lanes8 {
  __m512i s0, s1, s2, s3;

  [[gnu::always_inline]] __m512i next() {
    const __m512i result = _mm512_add_epi64(s0, s3);
    const __m512i t = _mm512_slli_epi64(s1, 17);
    s2 = _mm512_xor_si512(s2, s0);
    s3 = _mm512_xor_si512(s3, s1);
    s1 = _mm512_xor_si512(s1, s2);
    s0 = _mm512_xor_si512(s0, s3);
    s2 = _mm512_xor_si512(s2, t);
    s3 = _mm512_rol_epi64(s3, 45);
    return result;
  }
};

// wrap_unit of eight lanes: t − ⌊t⌋, and 0 where that is not below 1 (or is a NaN).
[[gnu::always_inline]] inline __m512d wrap_unit8(__m512d t) {
  const __m512d r =
      _mm512_sub_pd(t, _mm512_roundscale_pd(t, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
  return _mm512_maskz_mov_pd(_mm512_cmp_pd_mask(r, _mm512_set1_pd(1.0), _CMP_LT_OQ), r);
}

// One chaos-game step of the eight lanes: the maps drawn (one per 64-bit lane) and the new points
// (wrapped onto the torus of the tile with kWrap).
template <bool kSixteen, bool kWrap>
[[gnu::always_inline]] inline __m512i octo_step(const OctoTables& t, Lanes8& rng, __m512d& x,
                                                __m512d& y) {
  const __m512i r = rng.next();
  // column = ((r >> 32) · N) >> 32; map = low32(r) < threshold[column] ? column : alias[column]
  const __m512i column = _mm512_srli_epi64(_mm512_mul_epu32(_mm512_srli_epi64(r, 32), t.count), 32);
  const __mmask8 below = _mm512_cmplt_epu64_mask(_mm512_and_si512(r, _mm512_set1_epi64(0xffffffff)),
                                                 lookup<kSixteen>(t.threshold, column));
  const __m512i n = _mm512_mask_blend_epi64(below, lookup<kSixteen>(t.alias, column), column);
  // (a x + b y) + e, (c x + d y) + f: the scalar loop's order, rounded the same way.
  const __m512d nx = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(lookup<kSixteen>(t.a, n), x),
                                                 _mm512_mul_pd(lookup<kSixteen>(t.b, n), y)),
                                   lookup<kSixteen>(t.e, n));
  const __m512d ny = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(lookup<kSixteen>(t.c, n), x),
                                                 _mm512_mul_pd(lookup<kSixteen>(t.d, n), y)),
                                   lookup<kSixteen>(t.f, n));
  if constexpr (kWrap) {
    x = wrap_unit8(nx);
    y = wrap_unit8(ny);
  } else {
    x = nx;
    y = ny;
  }
  return n;
}

template <class Sink, bool kSixteen, bool kWrap>
void walk_octo(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  const OctoTables t = load_octo_tables(w);
  alignas(64) std::uint64_t s[4][kLanes];
  alignas(64) double x0[kLanes], y0[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    std::uint64_t rng[4] = {seeds.s[lane][0], seeds.s[lane][1], seeds.s[lane][2], seeds.s[lane][3]};
    x0[lane] = unit_interval(xoshiro_next(rng));
    y0[lane] = unit_interval(xoshiro_next(rng));
    for (int k = 0; k < 4; ++k) s[k][lane] = rng[k];
  }
  Lanes8 rng{_mm512_load_si512(s[0]), _mm512_load_si512(s[1]), _mm512_load_si512(s[2]),
             _mm512_load_si512(s[3])};
  __m512d x = _mm512_load_pd(x0), y = _mm512_load_pd(y0);
  __m512i key = _mm512_setzero_si512(), colour = _mm512_setzero_si512();
  // key = (key >> key_bits) | (map << (64 − key_bits)); c = (c + c_n) >> 1.
  const __m128i key_right = _mm_cvtsi32_si128(w.key_bits);
  const __m128i key_left = _mm_cvtsi32_si128(64 - w.key_bits);
  auto advance = [&] {
    const __m512i n = octo_step<kSixteen, kWrap>(t, rng, x, y);
    if constexpr (Sink::kKeys)
      key = _mm512_or_si512(_mm512_srl_epi64(key, key_right), _mm512_sll_epi64(n, key_left));
    if constexpr (Sink::kPalette)
      colour = _mm512_srli_epi64(_mm512_add_epi64(colour, lookup<kSixteen>(t.palette, n)), 1);
    return n;
  };
  for (int k = 0; k < w.burn_in; ++k) advance();

  const __m512d sx = _mm512_set1_pd(w.sx), ox = _mm512_set1_pd(w.ox);
  const __m512d sy = _mm512_set1_pd(w.sy), oy = _mm512_set1_pd(w.oy);
  const __m512d width = _mm512_set1_pd(w.width), height = _mm512_set1_pd(w.height);
  const __m512d zero = _mm512_setzero_pd();
  const __m256i stride = _mm256_set1_epi32(static_cast<int>(w.stride));
  // Pixel indices and maps of the lanes; plot those on the raster, in lane order.
  auto emit = [&](__mmask8 wanted, __m512i n) {
    const __m512d px = _mm512_add_pd(_mm512_mul_pd(sx, x), ox);
    const __m512d py = _mm512_add_pd(_mm512_mul_pd(sy, y), oy);
    unsigned mask = _mm512_cmp_pd_mask(px, zero, _CMP_GE_OQ) &
                    _mm512_cmp_pd_mask(px, width, _CMP_LT_OQ) &
                    _mm512_cmp_pd_mask(py, zero, _CMP_GE_OQ) &
                    _mm512_cmp_pd_mask(py, height, _CMP_LT_OQ) & wanted;
    if (mask == 0) return;
    alignas(32) std::int32_t index[kLanes];
    alignas(64) std::uint64_t map[kLanes], keys[kLanes] = {}, colours[kLanes] = {};
    alignas(64) double xs[kLanes] = {}, ys[kLanes] = {};
    _mm256_store_si256(reinterpret_cast<__m256i*>(index),
                       _mm256_add_epi32(_mm256_mullo_epi32(_mm512_cvttpd_epi32(py), stride),
                                        _mm512_cvttpd_epi32(px)));
    _mm512_store_si512(map, n);
    if constexpr (Sink::kKeys) _mm512_store_si512(keys, key);
    if constexpr (Sink::kPalette) _mm512_store_si512(colours, colour);
    if constexpr (Sink::kPoints) _mm512_store_pd(xs, x), _mm512_store_pd(ys, y);
    while (mask != 0) {
      const int j = __builtin_ctz(mask);
      mask &= mask - 1;
      sink.plot(j, static_cast<long>(index[j]), static_cast<std::uint32_t>(map[j]), keys[j],
                static_cast<std::uint32_t>(colours[j]), xs[j], ys[j]);
    }
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t k = 0; k < steps; ++k) emit(0xff, advance());
  const int rest = static_cast<int>(points % kLanes);
  if (rest > 0) emit(static_cast<__mmask8>((1u << rest) - 1), advance());
}

// Where each walker pays, measured with tests/ifs/kernel_levels_check on a Sapphire Rapids core
// (Mpts/s, AVX2 loop / this one): with up to 4 maps and no keys, the two independent chains of
// four lanes of walk_quads beat one chain of eight (hits 266/229 with 2 maps, measure 145/130
// with 3); with keys (tops) the eight lanes win at any size (256/387 with 2 maps), and from 5 maps
// on in every mode (hits 169/206 with 7 maps, measure 58/102 with 9, tops 69/270 with 9).
template <class Sink, bool kWrap>
void walk(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  if (w.maps <= 4 && !Sink::kKeys)
    walk_quads<Sink, false, kWrap>(w, seeds, points, sink);
  else if (w.maps <= 8)
    walk_octo<Sink, false, kWrap>(w, seeds, points, sink);
  else if (w.maps <= 16)
    walk_octo<Sink, true, kWrap>(w, seeds, points, sink);
  else
    walk_scalar<Sink, kWrap>(w, seeds, points, sink);
}

template <class Sink>
void walk(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  if (w.wrap)
    walk<Sink, true>(w, seeds, points, sink);
  else
    walk<Sink, false>(w, seeds, points, sink);
}

#include "ifs/detail/walk_kernels_table.inl"

}  // namespace

constexpr WalkKernels table = kernels;

}  // namespace ifsfx::detail::kernel_avx512
