// SPDX-License-Identifier: Apache-2.0
// The variations' batch forms (flame/detail/batch_variations.h): each is its registry function's
// formula (flame/variations_*.cpp, where the comments cite the paper) over the lane type V of
// flame/detail/vmath.inl, included after it. The random ones read their draws from t.u in the
// order the registry function draws them.

using flame::detail::BatchTerm;
using flame::detail::BatchVariation;
using flame::detail::kBatchStride;

constexpr double kBEps = 1e-10;  // the registry's kEps

struct VP {
  V x, y;
};

// (ox, oy) += f(x, y, i) for the points [0, n), kW at a time.
template <class F>
inline void each(std::size_t n, const double* X, const double* Y, double* OX, double* OY, F f) {
  for (std::size_t i = 0; i < n; i += kW) {
    const VP r = f(load(X + i), load(Y + i), i);
    store(OX + i, load(OX + i) + r.x);
    store(OY + i, load(OY + i) + r.y);
  }
}

inline V draw(const BatchTerm& t, int j, std::size_t i) {
  return load(t.u + static_cast<std::size_t>(j) * kBatchStride + i);
}

inline V r_of(V x, V y) { return vsqrt(x * x + y * y); }

#define IFSFX_BATCH(name) \
  void b_##name(const BatchTerm& t, std::size_t n, const double* X, const double* Y, double* OX, \
                double* OY)

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
    return VP{t.w * (sc.c * vcosh(y)), t.w * (-sc.s * vsinh(y))};
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
  const double p = t.params[0], d = t.params[1], ap = std::abs(p), e = d / p / 2;
  each(n, X, Y, OX, OY, [&](V x, V y, std::size_t i) {
    const V p3 = vtrunc(ap * draw(t, 0, i));
    const VSinCos sc = vsincos((vatan2(y, x) + 2.0 * kVPi * p3) / p);
    const V k = t.w * vpow(x * x + y * y, splat(e));
    return VP{k * sc.c, k * sc.s};
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

#undef IFSFX_BATCH

constexpr BatchVariation kTable[] = {
    {"linear", b_linear},
    {"sinusoidal", b_sinusoidal},
    {"spherical", b_spherical},
    {"swirl", b_swirl},
    {"horseshoe", b_horseshoe},
    {"polar", b_polar},
    {"handkerchief", b_handkerchief},
    {"heart", b_heart},
    {"disc", b_disc},
    {"spiral", b_spiral},
    {"hyperbolic", b_hyperbolic},
    {"diamond", b_diamond},
    {"ex", b_ex},
    {"julia", b_julia, 1},
    {"bent", b_bent},
    {"waves", b_waves},
    {"fisheye", b_fisheye},
    {"exponential", b_exponential},
    {"power", b_power},
    {"cosine", b_cosine},
    {"eyefish", b_eyefish},
    {"bubble", b_bubble},
    {"cylinder", b_cylinder},
    {"julian", b_julian, 1},
    {"blur", b_blur, 2},
    {"gaussian_blur", b_gaussian_blur, 5},
    {"curl", b_curl},
    {"tangent", b_tangent},
    {"square", b_square, 2},
    {"cross", b_cross},
};
