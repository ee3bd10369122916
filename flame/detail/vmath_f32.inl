// SPDX-License-Identifier: Apache-2.0
// vmath.inl's functions for float lanes (flame/detail/float_lanes.inl): the same names and
// reductions, with Cephes' single-precision polynomials (sinf, cosf, expf, atanf, tanhf) and
// shorter series, accurate to a few float ulps on the arguments flames produce. Only +, −, ×,
// ÷, √, comparisons and bit operations in one order for every level, no fused multiply-add, so
// each level gives the scalar level's bits. sin and cos of |x| > 8192 (where the three-part
// π/2 stops being exact, Cephes' limit) and of NaN go to libm lane by lane, on every level alike.

constexpr double kVPi = 3.14159265358979323846;
constexpr double kVMagic = 0x1.8p23;  // x + 1.5·2^23 − 1.5·2^23 rounds |x| < 2^22 to an integer
constexpr double kLn2Hi = 0.693359375, kLn2Lo = -2.12194440e-4;  // ln 2 = hi + lo, hi exact

// |x|: the sign bit cleared (one and, where a compare and a blend were).
inline V vabs(V x) {
  return from_bits(as_bits(x) & 0x7fffffffu);
}

// vround, vfloor and vtrunc are the level's (flame/detail/float_lanes.inl): one rounding
// instruction on AVX2, exact, so every level gives the same integers.

inline V vfmod(V x, V y) {
  return x - vtrunc(x / y) * y;
}

// 2^k for an integer-valued k in [−126, 127].
inline V pow2i(V k) {
  return from_bits((as_bits(k + kVMagic) + 127u) << 23);
}

// The lanes of x that the reduction cannot take, through libm: out of line, so that vsincos
// inlines without a call in its loop (a call would make every live register spill around it).
[[gnu::noinline, gnu::cold]] inline void wild_sincos(V x, V& sn, V& cs) {
  for (std::size_t i = 0; i < kW; ++i) {
    const float xi = lane(x, i);
    if (!(std::abs(xi) > 8192.0f || xi != xi)) continue;
    set_lane(sn, i, std::sin(xi));
    set_lane(cs, i, std::cos(xi));
  }
}

struct VSinCos {
  V s, c;
};

// sin and cos: x − k·π/2 (Cephes' three-part π/2, exact products for |x| ≤ 8192), the sinf and
// cosf polynomials on [−π/4, π/4], the quadrant k mod 4 from k's low bits as in vmath.inl.
[[gnu::always_inline]] inline VSinCos vsincos(V x) {
  const V k = vround(x * 6.36619772367581382433e-01);
  V r = x - k * 1.5703125;
  r = r - k * 4.837512969970703125e-4;
  r = r - k * 7.54978995489188216e-8;
  const V z = r * r;
  V ps = z * -1.9515295891e-4 + 8.3321608736e-3;
  ps = z * ps - 1.6666654611e-1;
  const V s = r + r * z * ps;
  V pc = z * 2.443315711809948e-5 - 1.388731625493765e-3;
  pc = z * pc + 4.166664568298827e-2;
  const V c = (1.0 - 0.5 * z) + z * z * pc;
  const I q = as_bits(k + kVMagic);
  const M odd = (q & 1u) != 0u;
  V sn = sel(odd, c, s), cs = sel(odd, s, c);
  sn = from_bits(as_bits(sn) ^ ((q & 2u) << 30));
  cs = from_bits(as_bits(cs) ^ (((q ^ (q >> 1)) & 1u) << 31));
  const M wild = (vabs(x) > 8192.0) | (x != x);
  if (any(wild)) [[unlikely]]
    wild_sincos(x, sn, cs);
  return {sn, cs};
}

inline V vsin(V x) {
  return vsincos(x).s;
}
inline V vcos(V x) {
  return vsincos(x).c;
}

// e^x: x − k·ln 2, Cephes' expf polynomial on |r| ≤ ln 2 / 2, times 2^k; 0 below −87.33 (the
// normal floats), ∞ above 88.72; k stops at 127, so e^x for x in (88, 88.72] is e^88·… short
// of its value (a point that far has escaped anyway).
inline V vexp(V x) {
  const V xc = sel(x > 88.0, splat(88.0), sel(x < -87.33, splat(-87.33), x));
  const V k = vround(xc * 1.44269504088896338700e+00);
  const V r = (xc - k * kLn2Hi) - k * kLn2Lo;
  V p = r * 1.9875691500e-4 + 1.3981999507e-3;
  p = p * r + 8.3334519073e-3;
  p = p * r + 4.1665795894e-2;
  p = p * r + 1.6666665459e-1;
  p = p * r + 5.0000001201e-1;
  const V e = (p * r * r + r + 1.0) * pow2i(k);
  return sel(x > 88.72, splat(HUGE_VAL), sel(x < -87.33, splat(0.0), e));
}

// ln x: x = 2^e·m with m in [√½, √2), ln m = 2·atanh((m − 1)/(m + 1)) by its series to the
// ninth power (the next term is below a float ulp); subnormal x scaled by 2^25 first; NaN for
// x < 0, −∞ at 0, ∞ at ∞.
inline V vlog(V x) {
  const M tiny = x < 0x1p-126;
  const V xs = sel(tiny, x * 0x1p25, x);
  const I b = as_bits(xs);
  V e = from_bits((b >> 23) | 0x4B000000u) - (0x1p23 + 127.0);
  e = sel(tiny, e - 25.0, e);
  V m = from_bits((b & 0x007fffffu) | 0x3f800000u);
  const M high = m > 1.41421356237309504880;
  m = sel(high, m * 0.5, m);
  e = sel(high, e + 1.0, e);
  const V s = (m - 1.0) / (m + 1.0), z = s * s;
  V p = z * (1.0 / 9) + 1.0 / 7;
  p = p * z + 1.0 / 5;
  p = p * z + 1.0 / 3;
  p = p * z + 1.0;
  const V l = e * kLn2Hi + (e * kLn2Lo + 2.0 * s * p);
  V out = sel(x == 0.0, splat(-HUGE_VAL), l);
  out = sel(x == HUGE_VAL, splat(HUGE_VAL), out);
  return sel((x < 0.0) | (x != x), splat(NAN), out);
}

inline V vpow(V x, V y) {
  return vexp(y * vlog(x));
}

// x^e for x ≥ 0 and a term's constant e: by square roots for e = ½ and ¼ (julian's and
// juliascope's d/(2p) at d = 1, p = 1 or 2; correctly rounded, where e^(e·ln x) was a log, a
// division and an exp), else vpow. The branch is the same for every point of the term.
inline V vpow_const(V x, double e) {
  if (e == 0.5) return vsqrt(x);
  if (e == 0.25) return vsqrt(vsqrt(x));
  return vpow(x, splat(e));
}

// atan on [−tan π/8, tan π/8] (Cephes' atanf polynomial).
inline V atan_core(V t) {
  const V z = t * t;
  V p = z * 8.05374449538e-2 - 1.38776856032e-1;
  p = p * z + 1.99777106478e-1;
  p = p * z - 3.33329491539e-1;
  return t + t * z * p;
}

// atan2(y, x) in (−π, π], as vmath.inl's: atan of the smaller over the larger |coordinate| a,
// above tan π/8 through atan a = π/4 + atan((a − 1)/(a + 1)), reflected into its octant. The
// quotient is taken once, numerator and denominator chosen first: (small − big)/(small + big)
// above tan π/8, small/big below (one division where there were two).
inline V vatan2(V y, V x) {
  const V ax = vabs(x), ay = vabs(y);
  const M swap = ay > ax;
  const V big = sel(swap, ay, ax), small = sel(swap, ax, ay);
  const M far = small > 0.41421356237309504880 * big;
  const V num = sel(far, small - big, small), den = sel(far, small + big, big);
  const V t = sel(big == 0.0, splat(0.0), num / den);
  V ang = atan_core(t) + sel(far, splat(kVPi / 4), splat(0.0));
  ang = sel(swap, kVPi / 2 - ang, ang);
  ang = sel(x < 0.0, kVPi - ang, ang);
  ang = sel(y < 0.0, -ang, ang);
  return sel((x != x) | (y != y), splat(NAN), ang);
}

inline V vatan(V x) {
  return vatan2(x, splat(1.0));
}

struct VSinhCosh {
  V s, c;
};

// sinh and cosh from one e^|x|; sinh by its Taylor series below 0.5.
inline VSinhCosh vsinhcosh(V x) {
  const V ax = vabs(x), e = vexp(ax), ie = 1.0 / e;
  const V big = 0.5 * (e - ie);
  const V z = x * x;
  V p = z * (1.0 / 5040.0) + 1.0 / 120.0;
  p = p * z + 1.0 / 6.0;
  const V small = ax + ax * z * p;
  const V s = sel(ax < 0.5, small, big);
  return {sel(x < 0.0, -s, s), 0.5 * (e + ie)};
}

inline V vsinh(V x) {
  return vsinhcosh(x).s;
}

inline V vcosh(V x) {
  return vsinhcosh(x).c;
}

// tanh: Cephes' tanhf polynomial below 0.625, 1 − 2/(e^2|x| + 1) above.
inline V vtanh(V x) {
  const V ax = vabs(x), z = x * x;
  V p = z * -5.70498872745e-3 + 2.06390887954e-2;
  p = p * z - 5.37397155531e-2;
  p = p * z + 1.33314422036e-1;
  p = p * z - 3.33332819422e-1;
  const V small = ax + ax * z * p;
  const V big = 1.0 - 2.0 / (vexp(2.0 * ax) + 1.0);
  const V t = sel(ax < 0.625, small, big);
  return sel(x < 0.0, -t, t);
}
