// SPDX-License-Identifier: Apache-2.0
// The lane type V of the variations' float batch forms: kW floats (one at the scalar level, eight
// on AVX2) that take part in the batch forms' formulas (flame/detail/batch_kernels.inl) as V of
// doubles does. A double or integer operand is rounded to float first, so that x·w is a float
// product on every level (C++ would widen float·double to double at the scalar level and refuse
// it for GCC's vectors). Included inside a level's anonymous namespace after it defines F (float
// or a GCC vector of kW floats), I (its bits as unsigned 32-bit integers), kW and
//   F splat_f(float), F sqrt_f(F), bool any_f(M), F load_f(const double*) (kW doubles rounded),
//   void add_to_f(double*, F) (kW doubles += the floats widened), F loadu_f(const float*) and
//   void storeu_f(float*, F) (kW floats, unaligned), F round_f(F), floor_f(F), trunc_f(F) (to
//   the nearest integer, ties to even, below, toward 0: exact, one instruction on AVX2),
// all with the same rounding on every level (IEEE single operations, no fused multiply-add).

using M = decltype(F{} < F{});

struct V {
  F v;
};

template <class S>
concept LaneScalar = std::is_arithmetic_v<S>;

// [[gnu::const]]: no side effects, so that the scalar level's masks (bool) combine with & and |
// without clang taking the call for one (-Wbitwise-instead-of-logical).
#define IFSFX_F32_OP(op)                             \
  [[gnu::const]] inline auto operator op(V a, V b) { \
    return wrap(a.v op b.v);                         \
  }                                                  \
  template <LaneScalar S>                            \
  [[gnu::const]] inline auto operator op(V a, S b) { \
    return wrap(a.v op static_cast<float>(b));       \
  }                                                  \
  template <LaneScalar S>                            \
  [[gnu::const]] inline auto operator op(S a, V b) { \
    return wrap(static_cast<float>(a) op b.v);       \
  }

// An arithmetic result is a lane again; a comparison's mask stays a mask.
inline V wrap(F f) {
  return {f};
}
inline M wrap(M m) {
  return m;
}

IFSFX_F32_OP(+)
IFSFX_F32_OP(-)
IFSFX_F32_OP(*)
IFSFX_F32_OP(/)
IFSFX_F32_OP(<)
IFSFX_F32_OP(>)
IFSFX_F32_OP(<=)
IFSFX_F32_OP(>=)
IFSFX_F32_OP(==)
IFSFX_F32_OP(!=)
#undef IFSFX_F32_OP

inline V operator-(V a) {
  return {-a.v};
}

inline V splat(double d) {
  return {splat_f(static_cast<float>(d))};
}
inline V load(const double* p) {
  return {load_f(p)};
}
inline void add_to(double* p, V v) {
  add_to_f(p, v.v);
}
// The float arrays of an xform's sum (BatchFunctionF): no conversion, the sum in float.
inline V load(const float* p) {
  return {loadu_f(p)};
}
inline void add_to(float* p, V v) {
  storeu_f(p, loadu_f(p) + v.v);
}
inline V sel(M m, V a, V b) {
  return {m ? a.v : b.v};
}
inline bool any(M m) {
  return any_f(m);
}
inline V vsqrt(V x) {
  return {sqrt_f(x.v)};
}
inline V vround(V x) {
  return {round_f(x.v)};
}
inline V vfloor(V x) {
  return {floor_f(x.v)};
}
inline V vtrunc(V x) {
  return {trunc_f(x.v)};
}
inline I as_bits(V x) {
  return bits_f(x.v);
}
inline V from_bits(I i) {
  return {floats_f(i)};
}
inline float lane(V x, std::size_t i) {
  return lane_f(x.v, i);
}
inline void set_lane(V& x, std::size_t i, float f) {
  set_lane_f(x.v, i, f);
}
