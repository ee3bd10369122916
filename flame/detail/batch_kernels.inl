// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms (flame/detail/batch_variations.h): each is its registry function's
// formula (flame/variations_*.cpp, where the comments cite the paper) over the lane type V of
// flame/detail/vmath.inl (doubles) or flame/detail/vmath_f32.inl (floats), included after it. The
// random ones read their draws from t.u in the order the registry function draws them. The level
// defines add_to(double* o, V r): o[0, kW) += r, in double. A float level (IFSFX_FLOAT_IO) also
// defines load(const float*) and add_to(float*, V), and each form has a second instance over
// float arrays (BatchFunctionF): the terms of an xform's sum read one float copy of its points
// and add into float sums, without a conversion each way for every term.

using flame::detail::BatchTerm;
using flame::detail::BatchVariation;
using flame::detail::kBatchStride;

constexpr double kBEps = 1e-10;  // the registry's kEps

struct VP {
  V x, y;
};

// (ox, oy) += f(x, y, i) for the points [0, n), kW at a time.
template <class In, class Out, class F>
inline void each(std::size_t n, const In* X, const In* Y, Out* OX, Out* OY, F f) {
  for (std::size_t i = 0; i < n; i += kW) {
    const VP r = f(load(X + i), load(Y + i), i);
    add_to(OX + i, r.x);
    add_to(OY + i, r.y);
  }
}

inline V draw(const BatchTerm& t, int j, std::size_t i) {
  return load(t.u + static_cast<std::size_t>(j) * kBatchStride + i);
}

inline V r_of(V x, V y) {
  return vsqrt(x * x + y * y);
}

// julian's and juliascope's w·(x² + y²)^e on the circle at angle_of(x, y, i), in passes: the
// radii, then the angles, then the points. In one pass its chain (atan2, then sincos) and its
// pow were more instructions than the core reorders at once, so one group of lanes waited for
// the last.
template <class In, class Out, class A>
inline void julian_passes(const BatchTerm& t, std::size_t n, const In* X, const In* Y, Out* OX,
                          Out* OY, double e, A angle_of) {
  V angle[kBatchStride / kW + 1], radius[kBatchStride / kW + 1];
  for (std::size_t i = 0; i < n; i += kW) {
    const V x = load(X + i), y = load(Y + i);
    radius[i / kW] = t.w * vpow_const(x * x + y * y, e);
  }
  for (std::size_t i = 0; i < n; i += kW) angle[i / kW] = angle_of(load(X + i), load(Y + i), i);
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const VSinCos sc = vsincos(angle[i / kW]);
    const V k = radius[i / kW];
    return VP{k * sc.c, k * sc.s};
  });
}

#define IFSFX_BATCH(name)        \
  template <class In, class Out> \
  void b_##name(const BatchTerm& t, std::size_t n, const In* X, const In* Y, Out* OX, Out* OY)

IFSFX_BATCH(linear) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) { return VP{t.w * x, t.w * y}; });
}
IFSFX_BATCH(sinusoidal) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) { return VP{t.w * vsin(x), t.w * vsin(y)}; });
}
IFSFX_BATCH(spherical) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = 1.0 / (x * x + y * y + kBEps);
    return VP{t.w * k * x, t.w * k * y};
  });
}
IFSFX_BATCH(swirl) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(x * x + y * y);
    return VP{t.w * (x * sc.s - y * sc.c), t.w * (x * sc.c + y * sc.s)};
  });
}
IFSFX_BATCH(horseshoe) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = 1.0 / (r_of(x, y) + kBEps);
    return VP{t.w * k * ((x - y) * (x + y)), t.w * k * (2.0 * x * y)};
  });
}
IFSFX_BATCH(polar) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (vatan2(x, y) / kVPi), t.w * (r_of(x, y) - 1.0)};
  });
}
IFSFX_BATCH(handkerchief) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y), a = vatan2(x, y);
    return VP{t.w * r * vsin(a + r), t.w * r * vcos(a - r)};
  });
}
IFSFX_BATCH(heart) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const VSinCos sc = vsincos(vatan2(x, y) * r);
    return VP{t.w * r * sc.s, t.w * r * -sc.c};
  });
}
IFSFX_BATCH(disc) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(kVPi * r_of(x, y));
    const V k = t.w * vatan2(x, y) / kVPi;
    return VP{k * sc.s, k * sc.c};
  });
}
IFSFX_BATCH(spiral) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r0 = r_of(x, y), r = r0 + kBEps;
    const VSinCos sc = vsincos(r);
    const V k = t.w / r;
    return VP{k * (y / (r0 + kBEps) + sc.s), k * (x / (r0 + kBEps) - sc.c)};
  });
}
IFSFX_BATCH(hyperbolic) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r0 = r_of(x, y), r = r0 + kBEps;
    return VP{t.w * (x / (r0 + kBEps) / r), t.w * (r * (y / (r0 + kBEps)))};
  });
}
IFSFX_BATCH(diamond) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const VSinCos sc = vsincos(r);
    return VP{t.w * (x / (r + kBEps) * sc.c), t.w * (y / (r + kBEps) * sc.s)};
  });
}
IFSFX_BATCH(ex) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y), a = vatan2(x, y);
    const V p0 = vsin(a + r), p1 = vcos(a - r);
    const V p03 = p0 * p0 * p0, p13 = p1 * p1 * p1;
    return VP{t.w * r * (p03 + p13), t.w * r * (p03 - p13)};
  });
}
IFSFX_BATCH(julia) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V a = vatan2(x, y) / 2.0 + sel(draw(t, 0, i) < 0.5, splat(0.0), splat(kVPi));
    const VSinCos sc = vsincos(a);
    const V k = t.w * vsqrt(r_of(x, y));
    return VP{k * sc.c, k * sc.s};
  });
}
IFSFX_BATCH(bent) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * sel(x < 0.0, 2.0 * x, x), t.w * sel(y < 0.0, y / 2.0, y)};
  });
}
IFSFX_BATCH(waves) {
  const AffineMap& m = *t.pre;
  const double kx = m.e * m.e + kBEps, ky = m.f * m.f + kBEps;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (x + m.b * vsin(y / kx)), t.w * (y + m.d * vsin(x / ky))};
  });
}
IFSFX_BATCH(fisheye) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = 2.0 / (r_of(x, y) + 1.0);
    return VP{t.w * k * y, t.w * k * x};
  });
}
IFSFX_BATCH(exponential) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = t.w * vexp(x - 1.0);
    const VSinCos sc = vsincos(kVPi * y);
    return VP{k * sc.c, k * sc.s};
  });
}
IFSFX_BATCH(power) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y), s = x / (r + kBEps), c = y / (r + kBEps);
    const V k = t.w * vpow(r, s);
    return VP{k * c, k * s};
  });
}
IFSFX_BATCH(cosine) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(kVPi * x);
    const VSinhCosh h = vsinhcosh(y);
    return VP{t.w * (sc.c * h.c), t.w * (-sc.s * h.s)};
  });
}
IFSFX_BATCH(eyefish) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = 2.0 / (r_of(x, y) + 1.0);
    return VP{t.w * k * x, t.w * k * y};
  });
}
IFSFX_BATCH(bubble) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = 4.0 / (x * x + y * y + 4.0);
    return VP{t.w * k * x, t.w * k * y};
  });
}
IFSFX_BATCH(cylinder) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) { return VP{t.w * vsin(x), t.w * y}; });
}
IFSFX_BATCH(julian) {
  const double p = t.params[0], d = t.params[1], ap = std::abs(p), ip = 1 / p;
  julian_passes(t, n, X, Y, OX, OY, d / p / 2, [&](V x, V y, std::size_t i) {
    const V p3 = vtrunc(ap * draw(t, 0, i));
    return (vatan2(y, x) + 2.0 * kVPi * p3) * ip;
  });
}
IFSFX_BATCH(blur) {
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const V k = t.w * draw(t, 0, i);
    const VSinCos sc = vsincos(2.0 * kVPi * draw(t, 1, i));
    return VP{k * sc.c, k * sc.s};
  });
}
IFSFX_BATCH(gaussian_blur) {
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const V g = draw(t, 0, i) + draw(t, 1, i) + draw(t, 2, i) + draw(t, 3, i) - 2.0;
    const VSinCos sc = vsincos(2.0 * kVPi * draw(t, 4, i));
    return VP{t.w * g * sc.c, t.w * g * sc.s};
  });
}
IFSFX_BATCH(curl) {
  const double c1 = t.params[0], c2 = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V t1 = 1.0 + c1 * x + c2 * (x * x - y * y), t2 = c1 * y + 2.0 * c2 * x * y;
    const V k = t.w * (1.0 / (t1 * t1 + t2 * t2 + kBEps));
    return VP{k * (x * t1 + y * t2), k * (y * t1 - x * t2)};
  });
}
IFSFX_BATCH(tangent) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sy = vsincos(y);
    return VP{t.w * (vsin(x) / sy.c), t.w * (sy.s / sy.c)};
  });
}
IFSFX_BATCH(square) {
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    return VP{t.w * (draw(t, 0, i) - 0.5), t.w * (draw(t, 1, i) - 0.5)};
  });
}
IFSFX_BATCH(cross) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V d = x * x - y * y;
    const V k = t.w * vsqrt(1.0 / (d * d + kBEps));
    return VP{k * x, k * y};
  });
}

// The complex functions (flame/variations_complex.cpp).
IFSFX_BATCH(exp) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V e = t.w * vexp(x);
    const VSinCos sc = vsincos(y);
    return VP{e * sc.c, e * sc.s};
  });
}
IFSFX_BATCH(log) {
  const double base = std::log(t.params[0]);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (0.5 * vlog(x * x + y * y) / base), t.w * vatan2(y, x)};
  });
}
IFSFX_BATCH(sin) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(x);
    const VSinhCosh h = vsinhcosh(y);
    return VP{t.w * (sc.s * h.c), t.w * (sc.c * h.s)};
  });
}
IFSFX_BATCH(cos) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(x);
    const VSinhCosh h = vsinhcosh(y);
    return VP{t.w * (sc.c * h.c), t.w * (-sc.s * h.s)};
  });
}
IFSFX_BATCH(tan) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(2.0 * x);
    const VSinhCosh h = vsinhcosh(2.0 * y);
    const V d = t.w * (1.0 / (sc.c + h.c));
    return VP{d * sc.s, d * h.s};
  });
}
IFSFX_BATCH(sec) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(x);
    const VSinhCosh h = vsinhcosh(y);
    // cos 2x + cosh 2y = 2(cos² x + sinh² y): no second sincos and sinhcosh.
    const V d = t.w * (1.0 / (sc.c * sc.c + h.s * h.s));
    return VP{d * (sc.c * h.c), d * (sc.s * h.s)};
  });
}
IFSFX_BATCH(csc) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(x);
    const VSinhCosh h = vsinhcosh(y);
    // cosh 2y − cos 2x = 2(sinh² y + sin² x): no second sincos and sinhcosh, no cancellation.
    const V d = t.w * (1.0 / (h.s * h.s + sc.s * sc.s));
    return VP{d * (sc.s * h.c), d * (-sc.c * h.s)};
  });
}
IFSFX_BATCH(cot) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(2.0 * x);
    const VSinhCosh h = vsinhcosh(2.0 * y);
    const V d = t.w * (1.0 / (h.c - sc.c));
    return VP{d * sc.s, d * -h.s};
  });
}
IFSFX_BATCH(sinh) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(y);
    const VSinhCosh h = vsinhcosh(x);
    return VP{t.w * (h.s * sc.c), t.w * (h.c * sc.s)};
  });
}
IFSFX_BATCH(cosh) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(y);
    const VSinhCosh h = vsinhcosh(x);
    return VP{t.w * (h.c * sc.c), t.w * (h.s * sc.s)};
  });
}
IFSFX_BATCH(tanh) {
  // sinh and cosh in a pass of their own (as julian's angle, for the reorder window).
  V sh[kBatchStride / kW + 1], ch[kBatchStride / kW + 1];
  for (std::size_t i = 0; i < n; i += kW) {
    const VSinhCosh h = vsinhcosh(2.0 * load(X + i));
    sh[i / kW] = h.s;
    ch[i / kW] = h.c;
  }
  each(n, X, Y, OX, OY, [&](V, V y, std::size_t i) {
    const VSinCos sc = vsincos(2.0 * y);
    const V d = t.w * (1.0 / (sc.c + ch[i / kW]));
    return VP{d * sh[i / kW], d * sc.s};
  });
}
IFSFX_BATCH(sech) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(y);
    const VSinhCosh h = vsinhcosh(x);
    // cos 2y + cosh 2x = 2(cos² y + sinh² x), as sec's.
    const V d = t.w * (1.0 / (sc.c * sc.c + h.s * h.s));
    return VP{d * (sc.c * h.c), d * (-sc.s * h.s)};
  });
}
IFSFX_BATCH(csch) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(y);
    const VSinhCosh h = vsinhcosh(x);
    // cosh 2x − cos 2y = 2(sinh² x + sin² y), as csc's.
    const V d = t.w * (1.0 / (h.s * h.s + sc.s * sc.s));
    return VP{d * (h.s * sc.c), d * (-h.c * sc.s)};
  });
}
IFSFX_BATCH(coth) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(2.0 * y);
    const VSinhCosh h = vsinhcosh(2.0 * x);
    const V d = t.w * (1.0 / (h.c - sc.c));
    return VP{d * h.s, d * sc.s};
  });
}

// flam3's later variations (flame/variations_flam3.cpp).
IFSFX_BATCH(popcorn2) {
  const double* k = t.params;
  // The tangents in a pass of their own (as julian's angle, for the reorder window).
  V ta[kBatchStride / kW + 1], tb[kBatchStride / kW + 1];
  for (std::size_t i = 0; i < n; i += kW) {
    const VSinCos a = vsincos(load(Y + i) * k[2]), b = vsincos(load(X + i) * k[2]);
    ta[i / kW] = a.s / a.c;
    tb[i / kW] = b.s / b.c;
  }
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    return VP{t.w * (x + k[0] * vsin(ta[i / kW])), t.w * (y + k[1] * vsin(tb[i / kW]))};
  });
}
IFSFX_BATCH(pie) {
  const double slices = t.params[0], rotation = t.params[1], thickness = t.params[2];
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const V t1 = vtrunc(draw(t, 0, i) * slices + 0.5);
    const V t2 = rotation + 2.0 * kVPi / slices * (t1 + draw(t, 1, i) * thickness);
    const VSinCos sc = vsincos(t2);
    const V k = t.w * draw(t, 2, i);
    return VP{k * sc.c, k * sc.s};
  });
}
IFSFX_BATCH(boarders) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V rx = vround(x), ry = vround(y), ox = x - rx, oy = y - ry;
    const V hx = ox * 0.5 + rx, hy = oy * 0.5 + ry;
    const V sx = sel(ox >= 0.0, splat(0.25), splat(-0.25));
    const V sy = sel(oy >= 0.0, splat(0.25), splat(-0.25));
    const M along_x = vabs(ox) >= vabs(oy), keep = draw(t, 0, i) >= 0.75;
    V px = sel(along_x, hx + sx, hx + sy * ox / oy);
    V py = sel(along_x, hy + sx * oy / ox, hy + sy);
    px = sel(keep, hx, px);
    py = sel(keep, hy, py);
    return VP{t.w * px, t.w * py};
  });
}
IFSFX_BATCH(super_shape) {
  const double* k = t.params;
  const double rnd = k[0], m = k[1], n1 = k[2], n2 = k[3], n3 = k[4], holes = k[5];
  // The radius factor (|cos a|^n2 + |sin a|^n3)^(−1/n1) at angle a, and a point's move by it.
  const auto factor = [&](V a) {
    const VSinCos sc = vsincos(a);
    const V t1 = vpow(vabs(sc.c), splat(n2)), t2 = vpow(vabs(sc.s), splat(n3));
    return vpow(t1 + t2, splat(-1 / n1));
  };
  const auto moved = [&](V x, V y, std::size_t i, V q) {
    const V r = r_of(x, y);
    const V f = t.w * ((rnd * draw(t, 0, i) + (1 - rnd) * r - holes) * q) / (r + kBEps);
    return VP{f * x, f * y};
  };
  if (m == 0) {
    // m = 0, as flam3-genome writes it: the angle is 0·atan2 + π/4 = π/4 at every point, so the
    // factor is one value for the term, by the same operations: the same bits, three pows and a
    // sincos fewer a point.
    const V q = factor(splat(kVPi / 4));
    each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) { return moved(x, y, i, q); });
    return;
  }
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    return moved(x, y, i, factor(m / 4 * vatan2(y, x) + kVPi / 4));
  });
}
IFSFX_BATCH(loonie) {
  const double w2 = t.w * t.w;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r2 = x * x + y * y;
    const V k = sel((r2 < w2) & (r2 != 0.0), t.w * vsqrt(w2 / r2 - 1.0), splat(t.w));
    return VP{k * x, k * y};
  });
}
// Inside the circle of radius w about (cx, −cy): turned by spin + twist·(w − r); outside: pushed
// out by space/r. Both sides computed, the lane's chosen.
IFSFX_BATCH(lazysusan) {
  const double spin = t.params[0], space = t.params[1], twist = t.params[2];
  const double cx = t.params[3], cy = t.params[4];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V xx = x - cx, yy = y + cy, rr = vsqrt(xx * xx + yy * yy);
    const VSinCos sc = vsincos(vatan2(yy, xx) + spin + twist * (t.w - rr));
    const V in = t.w * rr, s = t.w * (1.0 + space / (rr + kBEps));
    const M inside = rr < t.w;
    return VP{sel(inside, in * sc.c + cx, s * xx + cx), sel(inside, in * sc.s - cy, s * yy - cy)};
  });
}
IFSFX_BATCH(conic) {
  const double e = t.params[0], holes = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    // e/((1 + e·x/r)·r) as e/(r + e·x): one division where there were three.
    const V r = r_of(x, y) + kBEps;
    const V k = t.w * (draw(t, 0, i) - holes) * e / (r + e * x);
    return VP{k * x, k * y};
  });
}
IFSFX_BATCH(curve) {
  const double* k = t.params;
  const double xl = std::max(k[2] * k[2], 1e-20), yl = std::max(k[3] * k[3], 1e-20);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (x + k[0] * vexp(-y * y / xl)), t.w * (y + k[1] * vexp(-x * x / yl))};
  });
}
IFSFX_BATCH(flower) {
  const double petals = t.params[0], holes = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V r = t.w * (draw(t, 0, i) - holes) * vcos(petals * vatan2(y, x));
    const V k = r / (r_of(x, y) + kBEps);
    return VP{k * x, k * y};
  });
}
IFSFX_BATCH(whorl) {
  const double inside = t.params[0], outside = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const V turn = sel(r < t.w, splat(inside), splat(outside)) / (t.w - r);
    const VSinCos sc = vsincos(vatan2(y, x) + turn);
    return VP{t.w * r * sc.c, t.w * r * sc.s};
  });
}
IFSFX_BATCH(foci) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V ex = 0.5 * vexp(x), enx = 0.25 / ex;
    const VSinCos sc = vsincos(y);
    const V k = t.w / (ex + enx - sc.c);
    return VP{k * (ex - enx), k * sc.s};
  });
}
IFSFX_BATCH(bent2) {
  const double px = t.params[0], py = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * sel(x < 0.0, x * px, x), t.w * sel(y < 0.0, y * py, y)};
  });
}
IFSFX_BATCH(polar2) {
  const double k = t.w / kVPi;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{k * vatan2(x, y), k / 2 * vlog(x * x + y * y)};
  });
}
IFSFX_BATCH(waves2) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (x + k[0] * vsin(y * k[2])), t.w * (y + k[1] * vsin(x * k[3]))};
  });
}
IFSFX_BATCH(splits) {
  const double px = t.params[0], py = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * sel(x >= 0.0, x + px, x - px), t.w * sel(y >= 0.0, y + py, y - py)};
  });
}

// More of the paper's catalogue (flame/variations_paper.cpp).
IFSFX_BATCH(popcorn) {
  const AffineMap& m = *t.pre;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos a = vsincos(3.0 * y), b = vsincos(3.0 * x);
    return VP{t.w * (x + m.e * vsin(a.s / a.c)), t.w * (y + m.f * vsin(b.s / b.c))};
  });
}
IFSFX_BATCH(rings) {
  const double c2 = t.pre->e * t.pre->e + kBEps;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const V k = t.w * (vfmod(r + c2, splat(2 * c2)) - c2 + r * (1 - c2));
    return VP{k * (y / (r + kBEps)), k * (x / (r + kBEps))};
  });
}
IFSFX_BATCH(fan) {
  const double tt = kVPi * (t.pre->e * t.pre->e + kBEps), f = t.pre->f;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V theta = vatan2(x, y);
    const V a = sel(vfmod(theta + f, splat(tt)) > tt / 2, theta - tt / 2, theta + tt / 2);
    const VSinCos sc = vsincos(a);
    const V k = t.w * r_of(x, y);
    return VP{k * sc.c, k * sc.s};
  });
}
IFSFX_BATCH(blob) {
  const double high = t.params[0], low = t.params[1], waves_n = t.params[2];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r0 = r_of(x, y);
    const V r = r0 * (low + (high - low) / 2 * (vsin(waves_n * vatan2(x, y)) + 1.0));
    return VP{t.w * r * (x / (r0 + kBEps)), t.w * r * (y / (r0 + kBEps))};
  });
}
IFSFX_BATCH(pdj) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * (vsin(k[0] * y) - vcos(k[1] * x)), t.w * (vsin(k[2] * x) - vcos(k[3] * y))};
  });
}
IFSFX_BATCH(fan2) {
  const double p1 = kVPi * (t.params[0] * t.params[0] + kBEps), p2 = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V theta = vatan2(x, y);
    const V tt = theta + p2 - p1 * vtrunc((theta + p2) / p1);
    const VSinCos sc = vsincos(sel(tt > p1 / 2, theta - p1 / 2, theta + p1 / 2));
    const V k = t.w * r_of(x, y);
    return VP{k * sc.s, k * sc.c};
  });
}
IFSFX_BATCH(rings2) {
  const double p = t.params[0] * t.params[0] + kBEps;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const V k = t.w * (r - 2 * p * vtrunc((r + p) / (2 * p)) + r * (1 - p));
    return VP{k * (x / (r + kBEps)), k * (y / (r + kBEps))};
  });
}
IFSFX_BATCH(perspective) {
  const double a = t.params[0] * kVPi / 2, d = t.params[1];
  const double sa = std::sin(a), ca = std::cos(a);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = t.w * (d / (d - y * sa + kBEps));
    return VP{k * x, k * (y * ca)};
  });
}
IFSFX_BATCH(noise) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V k = t.w * draw(t, 0, i);
    const VSinCos sc = vsincos(2 * kVPi * draw(t, 1, i));
    return VP{k * (x * sc.c), k * (y * sc.s)};
  });
}
IFSFX_BATCH(juliascope) {
  const double p = t.params[0], d = t.params[1], ap = std::abs(p), ip = 1 / p;
  julian_passes(t, n, X, Y, OX, OY, d / p / 2, [&](V x, V y, std::size_t i) {
    const V p3 = vtrunc(ap * draw(t, 0, i));
    const V sign = sel(vfmod(p3, splat(2.0)) == 0.0, splat(1.0), splat(-1.0));
    return (sign * vatan2(y, x) + 2.0 * kVPi * p3) * ip;
  });
}
IFSFX_BATCH(radial_blur) {
  const double p1 = t.params[0] * kVPi / 2, s1 = std::sin(p1), c1 = std::cos(p1);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V g = draw(t, 0, i) + draw(t, 1, i) + draw(t, 2, i) + draw(t, 3, i) - 2.0;
    const V t1 = t.w * g, t2 = vatan2(y, x) + t1 * s1, t3 = t1 * c1 - 1.0;
    const VSinCos sc = vsincos(t2);
    const V r = r_of(x, y);
    return VP{r * sc.c + t3 * x, r * sc.s + t3 * y};
  });
}
IFSFX_BATCH(ngon) {
  const double sides = t.params[0], pw = t.params[1], circle = t.params[2];
  const double corners = t.params[3], p2 = 2 * kVPi / sides;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V phi = vatan2(y, x);
    V t3 = phi - p2 * vfloor(phi / p2);
    t3 = sel(t3 > p2 / 2, t3 - p2, t3);
    const V k = (corners * (1.0 / (vcos(t3) + kBEps) - 1.0) + circle) /
                (vpow(x * x + y * y, splat(pw / 2)) + kBEps);
    return VP{t.w * k * x, t.w * k * y};
  });
}
IFSFX_BATCH(rectangles) {
  const double px = t.params[0], py = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V nx = px == 0 ? x : (2.0 * vfloor(x / px) + 1.0) * px - x;
    const V ny = py == 0 ? y : (2.0 * vfloor(y / py) + 1.0) * py - y;
    return VP{t.w * nx, t.w * ny};
  });
}
IFSFX_BATCH(arch) {
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const VSinCos sc = vsincos(draw(t, 0, i) * kVPi * t.w);
    return VP{t.w * sc.s, t.w * (sc.s * sc.s / sc.c)};
  });
}
IFSFX_BATCH(rays) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const VSinCos a = vsincos(draw(t, 0, i) * kVPi * t.w);
    const V k = t.w * (t.w * (a.s / a.c) / (x * x + y * y + kBEps));
    return VP{k * vcos(x), k * vsin(y)};
  });
}
IFSFX_BATCH(blade) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const VSinCos sc = vsincos(draw(t, 0, i) * r_of(x, y) * t.w);
    return VP{t.w * x * (sc.c + sc.s), t.w * x * (sc.c - sc.s)};
  });
}
IFSFX_BATCH(secant2) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V c = vcos(t.w * r_of(x, y)), ic = 1.0 / c;
    return VP{t.w * x, t.w * sel(c < 0.0, ic + 1.0, ic - 1.0)};
  });
}

// More of flam3's (flame/variations_flam3.cpp, flame/variations_more.cpp).
IFSFX_BATCH(flux) {
  const double spread = 2 + t.params[0];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V xpw = x + t.w, xmw = x - t.w;
    const V ratio = vsqrt(y * y + xpw * xpw) / (vsqrt(y * y + xmw * xmw) + kBEps);
    const V r = t.w * spread * vsqrt(ratio);
    const VSinCos sc = vsincos((vatan2(y, xmw) - vatan2(y, xpw)) * 0.5);
    return VP{r * sc.c, r * sc.s};
  });
}
IFSFX_BATCH(disc2) {
  const double rot = t.params[0], twist = t.params[1];
  double sin_add = std::sin(twist), cos_add = std::cos(twist) - 1, k = 1;
  if (twist > 2 * kVPi) k = 1 + twist - 2 * kVPi;
  if (twist < -2 * kVPi) k = 1 + twist + 2 * kVPi;
  sin_add *= k;
  cos_add *= k;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const VSinCos sc = vsincos(rot * kVPi * (x + y));
    const V r = t.w * vatan2(x, y) / kVPi;
    return VP{(sc.s + cos_add) * r, (sc.c + sin_add) * r};
  });
}
IFSFX_BATCH(oscilloscope) {
  const double sep = t.params[0], freq = t.params[1], amp = t.params[2], damp = t.params[3];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V wave = amp * vcos(2 * kVPi * freq * x);
    const V tt = (damp == 0 ? wave : vexp(-vabs(x) * damp) * wave) + sep;
    return VP{t.w * x, t.w * sel(vabs(y) <= tt, -y, y)};
  });
}
IFSFX_BATCH(stripes) {
  const double space = t.params[0], warp = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V rx = vfloor(x + 0.5), ox = x - rx;
    return VP{t.w * (ox * (1 - space) + rx), t.w * (y + ox * ox * warp)};
  });
}
IFSFX_BATCH(hemisphere) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V k = t.w / vsqrt(x * x + y * y + 1.0);
    return VP{k * x, k * y};
  });
}
IFSFX_BATCH(parabola) {
  const double h = t.params[0], wd = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const VSinCos sc = vsincos(r_of(x, y));
    return VP{t.w * (h * sc.s * sc.s * draw(t, 0, i)), t.w * (wd * sc.c * draw(t, 1, i))};
  });
}
IFSFX_BATCH(butterfly) {
  const double c = 4 / std::sqrt(3 * kVPi);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V y2 = 2.0 * y;
    const V k = t.w * (c * vsqrt(vabs(x * y) / (x * x + y2 * y2 + kBEps)));
    return VP{k * x, k * y2};
  });
}
IFSFX_BATCH(scry) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r2 = x * x + y * y;
    const V k = 1.0 / (vsqrt(r2) * (r2 + 1 / (t.w + kBEps)) + kBEps);
    return VP{k * x, k * y};
  });
}
IFSFX_BATCH(split) {
  const double px = t.params[0], py = t.params[1];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V ny = sel(vcos(x * px * kVPi) >= 0.0, y, -y);
    const V nx = sel(vcos(y * py * kVPi) >= 0.0, x, -x);
    return VP{t.w * nx, t.w * ny};
  });
}
IFSFX_BATCH(escher) {
  const double vc = 0.5 * (1 + std::cos(t.params[0])), vd = 0.5 * std::sin(t.params[0]);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V a = vatan2(y, x), lnr = 0.5 * vlog(x * x + y * y);
    const V m = t.w * vexp(vc * lnr - vd * a);
    const VSinCos sc = vsincos(vc * a + vd * lnr);
    return VP{m * sc.c, m * sc.s};
  });
}
IFSFX_BATCH(cell) {
  const double size = t.params[0], inv = 1 / (size + kBEps);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    V cx = vfloor(x * inv), cy = vfloor(y * inv);
    const V dx = x - cx * size, dy = y - cy * size;
    cx = sel(cx >= 0.0, 2.0 * cx, -(2.0 * cx + 1.0));
    cy = sel(cy >= 0.0, 2.0 * cy, -(2.0 * cy + 1.0));
    return VP{t.w * (dx + cx * size), t.w * -(dy + cy * size)};
  });
}
// flam3's mobius and Apophysis' Mobius: w·(a·z + b)/(c·z + d), parameters re a, im a, … im d.
IFSFX_BATCH(mobius) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V ur = k[0] * x - k[1] * y + k[2], ui = k[0] * y + k[1] * x + k[3];
    const V vr = k[4] * x - k[5] * y + k[6], vi = k[4] * y + k[5] * x + k[7];
    const V s = t.w / (vr * vr + vi * vi + kBEps);
    return VP{s * (ur * vr + ui * vi), s * (ui * vr - ur * vi)};
  });
}

// The wedges' angle: a·(1 − angle·count/2π) + ⌊(count·a + π)/2π⌋·angle.
inline V wedge_angle(V a, double angle, double count) {
  const V c = vfloor((count * a + kVPi) / (2 * kVPi));
  return a * (1 - angle * count / (2 * kVPi)) + c * angle;
}
IFSFX_BATCH(wedge) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = r_of(x, y);
    const VSinCos sc = vsincos(wedge_angle(vatan2(y, x) + k[3] * r, k[0], k[2]));
    const V f = t.w * (r + k[1]);
    return VP{f * sc.c, f * sc.s};
  });
}
IFSFX_BATCH(wedge_julia) {
  const double angle = t.params[0], count = t.params[1], pw = t.params[2], dist = t.params[3];
  const double ap = std::abs(pw), e = dist / pw / 2;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V r = t.w * vpow(x * x + y * y, splat(e));
    const V branch = vtrunc(ap * draw(t, 0, i));
    const VSinCos sc = vsincos(wedge_angle((vatan2(y, x) + 2 * kVPi * branch) / pw, angle, count));
    return VP{r * sc.c, r * sc.s};
  });
}
IFSFX_BATCH(wedge_sph) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r = 1.0 / (r_of(x, y) + kBEps);
    const VSinCos sc = vsincos(wedge_angle(vatan2(y, x) + k[3] * r, k[0], k[1]));
    const V f = t.w * (r + k[2]);
    return VP{f * sc.c, f * sc.s};
  });
}
inline V wrap_into(V v, double m) {
  const V above = -m + vfmod(v + m, splat(2 * m)), below = m - vfmod(m - v, splat(2 * m));
  return sel(v > m, above, sel(v < -m, below, v));
}
IFSFX_BATCH(modulus) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * wrap_into(x, t.params[0]), t.w * wrap_into(y, t.params[1])};
  });
}
inline V separate(V v, double s, double inside) {
  const V h = vsqrt(v * v + s * s);
  return sel(v > 0.0, h - v * inside, -(h + v * inside));
}
IFSFX_BATCH(separation) {
  const double* k = t.params;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    return VP{t.w * separate(x, k[0], k[1]), t.w * separate(y, k[2], k[3])};
  });
}
IFSFX_BATCH(bipolar) {
  const double half = kVPi / 2, shift = half * t.params[0];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V r2 = x * x + y * y, tt = r2 + 1.0, x2 = 2.0 * x;
    V v = 0.5 * vatan2(2.0 * y, r2 - 1.0) - shift;
    v = sel(v > half, -half + vfmod(v + half, splat(kVPi)),
            sel(v < -half, half - vfmod(half - v, splat(kVPi)), v));
    const V u = 0.25 * vlog((tt + x2) / (tt - x2));
    return VP{t.w * 2 / kVPi * u, t.w * 2 / kVPi * v};
  });
}
IFSFX_BATCH(elliptic) {
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V tt = x * x + y * y + 1.0, x2 = 2.0 * x;
    const V xmax = 0.5 * (vsqrt(tt + x2) + vsqrt(tt - x2));
    const V a = x / xmax, one = 1.0 - a * a, xm = xmax - 1.0;
    const V b = vsqrt(sel(one > 0.0, one, splat(0.0)));
    const V ssx = vsqrt(sel(xm > 0.0, xm, splat(0.0)));
    const double w = t.w / (kVPi / 2);
    const V v = vlog(xmax + ssx);
    return VP{w * vatan2(a, b), sel(y > 0.0, w * v, -w * v)};
  });
}
// acos(c) as atan2(√((1 − c)(1 + c)), c), the product form keeping its digits near c = ±1.
IFSFX_BATCH(edisc) {
  const double w = t.w / 11.57034632;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t) {
    const V tt = x * x + y * y + 1.0, x2 = 2.0 * x;
    const V xmax = (vsqrt(tt + x2) + vsqrt(tt - x2)) / 2.0, xm = xmax - 1.0;
    const V a1 = vlog(xmax + vsqrt(sel(xm > 0.0, xm, splat(0.0))));
    V c = x / xmax;
    c = sel(c > 1.0, splat(1.0), sel(c < -1.0, splat(-1.0), c));
    const V a2 = -vatan2(vsqrt((1.0 - c) * (1.0 + c)), c);
    const VSinCos sc = vsincos(a1);
    const VSinhCosh h = vsinhcosh(a2);
    return VP{w * h.c * sc.c, w * h.s * sel(y > 0.0, -sc.s, sc.s)};
  });
}
IFSFX_BATCH(sineblur) {
  const double pw = std::max(t.params[0], 0.0);
  each(n, X, Y, OX, OY, [&](V, V, std::size_t i) {
    const VSinCos sc = vsincos(2 * kVPi * draw(t, 0, i));
    const V u = pw == 1 ? draw(t, 1, i) : vpow(draw(t, 1, i), splat(pw));
    const V c = 2.0 * u - 1.0;  // acos c = atan2(√(1 − c²), c)
    const V r = t.w * vatan2(vsqrt(1.0 - c * c), c) / kVPi;
    return VP{r * sc.c, r * sc.s};
  });
}
IFSFX_BATCH(blur_linear) {
  const double a = t.params[1], ca = std::cos(a), sa = std::sin(a);
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V r = t.params[0] * draw(t, 0, i);
    return VP{t.w * (x + r * ca), t.w * (y + r * sa)};
  });
}
IFSFX_BATCH(blur_zoom) {
  const double cx = t.params[1], cy = t.params[2];
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V z = 1.0 + t.params[0] * draw(t, 0, i);
    return VP{t.w * ((x - cx) * z + cx), t.w * ((y - cy) * z + cy)};
  });
}

#undef IFSFX_BATCH

// A form's double and (at a float level) float instances, then its draws.
#ifdef IFSFX_FLOAT_IO
#define IFSFX_FORMS(fn) fn<double, double>, fn<float, float>
#else
#define IFSFX_FORMS(fn) fn<double, double>, nullptr
#endif

constexpr BatchVariation kTable[] = {
    {"linear", IFSFX_FORMS(b_linear), 0},
    {"sinusoidal", IFSFX_FORMS(b_sinusoidal), 0},
    {"spherical", IFSFX_FORMS(b_spherical), 0},
    {"swirl", IFSFX_FORMS(b_swirl), 0},
    {"horseshoe", IFSFX_FORMS(b_horseshoe), 0},
    {"polar", IFSFX_FORMS(b_polar), 0},
    {"handkerchief", IFSFX_FORMS(b_handkerchief), 0},
    {"heart", IFSFX_FORMS(b_heart), 0},
    {"disc", IFSFX_FORMS(b_disc), 0},
    {"spiral", IFSFX_FORMS(b_spiral), 0},
    {"hyperbolic", IFSFX_FORMS(b_hyperbolic), 0},
    {"diamond", IFSFX_FORMS(b_diamond), 0},
    {"ex", IFSFX_FORMS(b_ex), 0},
    {"julia", IFSFX_FORMS(b_julia), 1},
    {"bent", IFSFX_FORMS(b_bent), 0},
    {"waves", IFSFX_FORMS(b_waves), 0},
    {"fisheye", IFSFX_FORMS(b_fisheye), 0},
    {"exponential", IFSFX_FORMS(b_exponential), 0},
    {"power", IFSFX_FORMS(b_power), 0},
    {"cosine", IFSFX_FORMS(b_cosine), 0},
    {"eyefish", IFSFX_FORMS(b_eyefish), 0},
    {"bubble", IFSFX_FORMS(b_bubble), 0},
    {"cylinder", IFSFX_FORMS(b_cylinder), 0},
    {"julian", IFSFX_FORMS(b_julian), 1},
    {"blur", IFSFX_FORMS(b_blur), 2},
    {"gaussian_blur", IFSFX_FORMS(b_gaussian_blur), 5},
    {"curl", IFSFX_FORMS(b_curl), 0},
    {"tangent", IFSFX_FORMS(b_tangent), 0},
    {"square", IFSFX_FORMS(b_square), 2},
    {"cross", IFSFX_FORMS(b_cross), 0},
    {"exp", IFSFX_FORMS(b_exp), 0},
    {"log", IFSFX_FORMS(b_log), 0},
    {"sin", IFSFX_FORMS(b_sin), 0},
    {"cos", IFSFX_FORMS(b_cos), 0},
    {"tan", IFSFX_FORMS(b_tan), 0},
    {"sec", IFSFX_FORMS(b_sec), 0},
    {"csc", IFSFX_FORMS(b_csc), 0},
    {"cot", IFSFX_FORMS(b_cot), 0},
    {"sinh", IFSFX_FORMS(b_sinh), 0},
    {"cosh", IFSFX_FORMS(b_cosh), 0},
    {"tanh", IFSFX_FORMS(b_tanh), 0},
    {"sech", IFSFX_FORMS(b_sech), 0},
    {"csch", IFSFX_FORMS(b_csch), 0},
    {"coth", IFSFX_FORMS(b_coth), 0},
    {"popcorn2", IFSFX_FORMS(b_popcorn2), 0},
    {"pie", IFSFX_FORMS(b_pie), 3},
    {"boarders", IFSFX_FORMS(b_boarders), 1},
    {"super_shape", IFSFX_FORMS(b_super_shape), 1},
    {"loonie", IFSFX_FORMS(b_loonie), 0},
    {"lazysusan", IFSFX_FORMS(b_lazysusan), 0},
    {"conic", IFSFX_FORMS(b_conic), 1},
    {"curve", IFSFX_FORMS(b_curve), 0},
    {"flower", IFSFX_FORMS(b_flower), 1},
    {"whorl", IFSFX_FORMS(b_whorl), 0},
    {"foci", IFSFX_FORMS(b_foci), 0},
    {"bent2", IFSFX_FORMS(b_bent2), 0},
    {"polar2", IFSFX_FORMS(b_polar2), 0},
    {"waves2", IFSFX_FORMS(b_waves2), 0},
    {"splits", IFSFX_FORMS(b_splits), 0},
    {"popcorn", IFSFX_FORMS(b_popcorn), 0},
    {"rings", IFSFX_FORMS(b_rings), 0},
    {"fan", IFSFX_FORMS(b_fan), 0},
    {"blob", IFSFX_FORMS(b_blob), 0},
    {"pdj", IFSFX_FORMS(b_pdj), 0},
    {"fan2", IFSFX_FORMS(b_fan2), 0},
    {"rings2", IFSFX_FORMS(b_rings2), 0},
    {"perspective", IFSFX_FORMS(b_perspective), 0},
    {"noise", IFSFX_FORMS(b_noise), 2},
    {"juliascope", IFSFX_FORMS(b_juliascope), 1},
    {"radial_blur", IFSFX_FORMS(b_radial_blur), 4},
    {"ngon", IFSFX_FORMS(b_ngon), 0},
    {"rectangles", IFSFX_FORMS(b_rectangles), 0},
    {"arch", IFSFX_FORMS(b_arch), 1},
    {"rays", IFSFX_FORMS(b_rays), 1},
    {"blade", IFSFX_FORMS(b_blade), 1},
    {"secant2", IFSFX_FORMS(b_secant2), 0},
    {"flux", IFSFX_FORMS(b_flux), 0},
    {"disc2", IFSFX_FORMS(b_disc2), 0},
    {"oscilloscope", IFSFX_FORMS(b_oscilloscope), 0},
    {"stripes", IFSFX_FORMS(b_stripes), 0},
    {"hemisphere", IFSFX_FORMS(b_hemisphere), 0},
    {"parabola", IFSFX_FORMS(b_parabola), 2},
    {"butterfly", IFSFX_FORMS(b_butterfly), 0},
    {"scry", IFSFX_FORMS(b_scry), 0},
    {"split", IFSFX_FORMS(b_split), 0},
    {"escher", IFSFX_FORMS(b_escher), 0},
    {"cell", IFSFX_FORMS(b_cell), 0},
    {"mobius", IFSFX_FORMS(b_mobius), 0},
    {"Mobius", IFSFX_FORMS(b_mobius), 0},
    {"linear3D", IFSFX_FORMS(b_linear), 0},
    {"wedge", IFSFX_FORMS(b_wedge), 0},
    {"wedge_julia", IFSFX_FORMS(b_wedge_julia), 1},
    {"wedge_sph", IFSFX_FORMS(b_wedge_sph), 0},
    {"modulus", IFSFX_FORMS(b_modulus), 0},
    {"separation", IFSFX_FORMS(b_separation), 0},
    {"bipolar", IFSFX_FORMS(b_bipolar), 0},
    {"elliptic", IFSFX_FORMS(b_elliptic), 0},
    {"edisc", IFSFX_FORMS(b_edisc), 0},
    {"sineblur", IFSFX_FORMS(b_sineblur), 2},
    {"blur_linear", IFSFX_FORMS(b_blur_linear), 1},
    {"blur_zoom", IFSFX_FORMS(b_blur_zoom), 1},
};

#undef IFSFX_FORMS
