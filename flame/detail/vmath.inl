// SPDX-License-Identifier: Apache-2.0
// Branch-free sin, cos, atan2, exp, log and their kin over a lane type V (double at the scalar
// level, four doubles on AVX2), for the variations' batch forms (flame/detail/batch_variations.h).
// Included inside each level's anonymous namespace after it defines V, M (a comparison's mask),
// I (V's bits as unsigned integers), kW and splat, load, store, sel, any, vsqrt, as_bits,
// from_bits, lane, set_lane. Only +, −, ×, ÷, √, comparisons and bit operations, in one order for
// every level, no fused multiply-add: each level gives the same bits. Accurate to a few units in
// the last place on the arguments flames produce (the fdlibm/Cephes reductions and polynomials);
// sin and cos of |x| > 10⁵ (and of NaN) go to libm lane by lane, on every level alike.

constexpr double kVPi = 3.14159265358979323846;
constexpr double kVMagic = 0x1.8p52;  // x + 1.5·2^52 − 1.5·2^52 rounds |x| < 2^51 to an integer
constexpr double kLn2Hi = 6.93147180369123816490e-01, kLn2Lo = 1.90821492927058770002e-10;

inline V vabs(V x) {
  return sel(x < 0.0, -x, x);
}

// The nearest integer (ties to even), for |x| < 2^51; larger |x| are integers already.
inline V vround(V x) {
  const V r = (x + kVMagic) - kVMagic;
  return sel(vabs(x) < 0x1p51, r, x);
}

inline V vfloor(V x) {
  const V r = vround(x);
  return sel(r > x, r - 1.0, r);
}

inline V vtrunc(V x) {
  const V f = vfloor(vabs(x));
  return sel(x < 0.0, -f, f);
}

// fmod(x, y) as libm: x − trunc(x/y)·y, the dividend's sign (exact for the flames' small
// quotients).
inline V vfmod(V x, V y) {
  return x - vtrunc(x / y) * y;
}

// 2^k for an integer-valued k in [−1022, 1023]: k's low bits from the rounding constant, moved
// into the exponent field.
inline V pow2i(V k) {
  return from_bits((as_bits(k + kVMagic) + 1023) << 52);
}

// The lanes of x that the reduction cannot take, through libm: out of line, so that vsincos
// inlines without a call in its loop (a call would make every live register spill around it).
[[gnu::noinline, gnu::cold]] inline void wild_sincos(V x, V& sn, V& cs) {
  for (std::size_t i = 0; i < kW; ++i) {
    const double xi = lane(x, i);
    if (!(std::abs(xi) > 1e5 || xi != xi)) continue;
    set_lane(sn, i, std::sin(xi));
    set_lane(cs, i, std::cos(xi));
  }
}

struct VSinCos {
  V s, c;
};

// sin and cos: x − k·π/2 (fdlibm's three-part π/2, exact products for |k| < 2^20), then the
// kernels' polynomials on [−π/4, π/4] and the quadrant k mod 4.
[[gnu::always_inline]] inline VSinCos vsincos(V x) {
  const V k = vround(x * 6.36619772367581382433e-01);
  V r = x - k * 1.57079632673412561417e+00;
  r = r - k * 6.07710050630396597660e-11;
  r = r - k * 2.02226624871116645580e-21;
  const V z = r * r;
  V ps = z * 1.58969099521155010221e-10 - 2.50507602534068634195e-08;
  ps = z * ps + 2.75573137070700676789e-06;
  ps = z * ps - 1.98412698298579493134e-04;
  ps = z * ps + 8.33333333332248946124e-03;
  ps = z * ps - 1.66666666666666324348e-01;
  const V s = r + r * z * ps;
  V pc = z * -1.13596475577881948265e-11 + 2.08757232129817482790e-09;
  pc = z * pc - 2.75573143513906633035e-07;
  pc = z * pc + 2.48015872894767294178e-05;
  pc = z * pc - 1.38888888888741095749e-03;
  pc = z * pc + 4.16666666666666019037e-02;
  const V c = (1.0 - 0.5 * z) + z * z * pc;
  // The quadrant k mod 4 is the low two bits of k + 1.5·2^52 (|k| < 2^17 here; wilder x below):
  // odd quadrants swap sin and cos, quadrants 2 and 3 negate sin, 1 and 2 negate cos (the sign
  // bit flipped, as −x does).
  const I q = as_bits(k + kVMagic);
  const M odd = (q & 1) != 0;
  V sn = sel(odd, c, s), cs = sel(odd, s, c);
  sn = from_bits(as_bits(sn) ^ ((q & 2) << 62));
  cs = from_bits(as_bits(cs) ^ (((q ^ (q >> 1)) & 1) << 63));
  const M wild = (vabs(x) > 1e5) | (x != x);
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

// e^x: x − k·ln 2 (fdlibm's two-part ln 2), Taylor to degree 13 on |r| ≤ ln 2 / 2, times 2^k;
// 0 below −708.39, ∞ above 709.78 (where 2^k leaves the normal numbers).
inline V vexp(V x) {
  const V xc = sel(x > 709.78, splat(709.78), sel(x < -708.39, splat(-708.39), x));
  const V k = vround(xc * 1.44269504088896338700e+00);
  const V r = (xc - k * kLn2Hi) - k * kLn2Lo;
  V p = r * (1.0 / 6227020800.0) + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  const V e = p * pow2i(k);
  return sel(x > 709.78, splat(HUGE_VAL), sel(x < -708.39, splat(0.0), e));
}

// ln x: x = 2^e·m with m in [√½, √2), ln m = 2·atanh((m − 1)/(m + 1)) by its series; subnormal
// x scaled by 2^54 first; NaN for x < 0, −∞ at 0, ∞ at ∞.
inline V vlog(V x) {
  const M tiny = x < 0x1p-1022;
  const V xs = sel(tiny, x * 0x1p54, x);
  const I b = as_bits(xs);
  V e = from_bits((b >> 52) | 0x4330000000000000ULL) - (0x1p52 + 1023.0);
  e = sel(tiny, e - 54.0, e);
  V m = from_bits((b & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  const M high = m > 1.41421356237309504880;
  m = sel(high, m * 0.5, m);
  e = sel(high, e + 1.0, e);
  const V s = (m - 1.0) / (m + 1.0), z = s * s;
  V p = z * (1.0 / 23) + 1.0 / 21;
  p = p * z + 1.0 / 19;
  p = p * z + 1.0 / 17;
  p = p * z + 1.0 / 15;
  p = p * z + 1.0 / 13;
  p = p * z + 1.0 / 11;
  p = p * z + 1.0 / 9;
  p = p * z + 1.0 / 7;
  p = p * z + 1.0 / 5;
  p = p * z + 1.0 / 3;
  p = p * z + 1.0;
  const V l = e * kLn2Hi + (e * kLn2Lo + 2.0 * s * p);
  V out = sel(x == 0.0, splat(-HUGE_VAL), l);
  out = sel(x == HUGE_VAL, splat(HUGE_VAL), out);
  return sel((x < 0.0) | (x != x), splat(NAN), out);
}

// x^y for x > 0 (and 0^y = 0 for y > 0), as e^(y·ln x).
inline V vpow(V x, V y) {
  return vexp(y * vlog(x));
}

// x^e for a term's constant e (vmath_f32.inl takes square roots for e = ½ and ¼; the double
// forms keep their bits).
inline V vpow_const(V x, double e) {
  return vpow(x, splat(e));
}

// atan on [−0.2, 0.66] (Cephes' rational form).
inline V atan_core(V t) {
  const V z = t * t;
  V p = z * -8.750608600031904122785e-01 - 1.615753718733365076637e+01;
  p = p * z - 7.500855792314704667340e+01;
  p = p * z - 1.228866684490136173410e+02;
  p = p * z - 6.485021904942025371773e+01;
  V q = z + 2.485846490142306297962e+01;
  q = q * z + 1.650270098316988542046e+02;
  q = q * z + 4.328810604912902668951e+02;
  q = q * z + 4.853903996359136964868e+02;
  q = q * z + 1.945506571482613964425e+02;
  return t + t * z * p / q;
}

// atan2(y, x) in (−π, π]: the angle of the smaller over the larger |coordinate| in [0, π/4],
// reflected into its octant.
inline V vatan2(V y, V x) {
  const V ax = vabs(x), ay = vabs(y);
  const V big = sel(ax > ay, ax, ay), small = sel(ax > ay, ay, ax);
  const V a = sel(big > 0.0, small / big, splat(0.0));
  const M far = a > 0.66;
  const V t = sel(far, (a - 1.0) / (a + 1.0), a);
  V ang = atan_core(t) + sel(far, splat(kVPi / 4), splat(0.0));
  ang = sel(ay > ax, kVPi / 2 - ang, ang);
  ang = sel(x < 0.0, kVPi - ang, ang);
  ang = sel(y < 0.0, -ang, ang);
  return sel((x != x) | (y != y), splat(NAN), ang);
}

inline V vatan(V x) {
  return vatan2(x, splat(1.0));
}

// sinh and cosh from one e^|x|; sinh by its Taylor series below 0.5, where e^x − e^−x cancels.
struct VSinhCosh {
  V s, c;
};

inline VSinhCosh vsinhcosh(V x) {
  const V ax = vabs(x), e = vexp(ax), ie = 1.0 / e;
  const V big = 0.5 * (e - ie);
  const V z = x * x;
  V p = z * (1.0 / 6227020800.0) + 1.0 / 39916800.0;
  p = p * z + 1.0 / 362880.0;
  p = p * z + 1.0 / 5040.0;
  p = p * z + 1.0 / 120.0;
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

inline V vtanh(V x) {
  const VSinhCosh h = vsinhcosh(x);
  return sel(vabs(x) > 20.0, sel(x < 0.0, splat(-1.0), splat(1.0)), h.s / h.c);
}
