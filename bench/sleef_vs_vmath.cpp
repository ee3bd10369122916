// SPDX-License-Identifier: Apache-2.0
// Issue 31 asks for the flame variations' transcendental functions vectorised, "Debian's SLEEF
// or Highway where they beat scalar libm". ifsfx's batch forms run on its own branch-free
// functions (flame/detail/vmath_f32.inl: no FMA, so that the AVX2 level gives the scalar
// level's bits). This program times them against SLEEF's: three variations whose cost is their
// transcendental functions — sinusoidal (sin), exponential (exp, sincos), julian (atan2, sincos,
// pow) — over batches of 256 points as the renderer runs them, in nanoseconds per point (best of
// several rounds), as
//   ifsfx     the variation's batch form at the AVX2 level in float lanes (the renderer's);
//   sleef     the same formula over SLEEF's AVX2 functions (Sleef_*f8_u35avx2, pow and exp at
//             1.0 ulp: u10), FMA and all;
//   sleef-avx the same over SLEEF's AVX functions (no FMA: the only SLEEF build whose bits a
//             scalar reference without FMA could give);
//   libm      the registry's function (flame/variations.h): double, point by point;
// and the largest difference of each from the registry's double result (the float forms round
// the points to float: a few 1e-6 of the result's size).
//   build/release/bench/sleef_vs_vmath        (built where libsleef-dev is installed, with
//                                             -mavx2: it runs on AVX2 machines only)
#include <immintrin.h>
#include <sleef.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "flame/detail/batch_variations.h"
#include "flame/variations.h"
#include "ifs/cpu.h"
#include "ifs/rng.h"

namespace {

using namespace ifsfx;
using flame::detail::BatchTerm;
using flame::detail::kBatchStride;

constexpr std::size_t kN = flame::detail::kBatchLanes;
constexpr int kRounds = 7, kRepeats = 4000;

struct Batch {
  std::vector<double> x, y, u, ox, oy;
};

// A formula over eight float lanes: (x, y, the draw) → w·V, as the batch forms take them.
struct Lanes {
  __m256 x, y;
};

// Sleef's functions for one build (AVX2 with FMA, or AVX without).
struct Sleef {
  decltype(&Sleef_sinf8_u35avx2) sin;
  decltype(&Sleef_sincosf8_u35avx2) sincos;
  decltype(&Sleef_atan2f8_u35avx2) atan2;
  decltype(&Sleef_expf8_u10avx2) exp;
  decltype(&Sleef_powf8_u10avx2) pow;
};

__m256 to_float(const double* p) {
  const __m128 lo = _mm256_cvtpd_ps(_mm256_loadu_pd(p)),
               hi = _mm256_cvtpd_ps(_mm256_loadu_pd(p + 4));
  return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}
void add_to(double* p, __m256 v) {
  _mm256_storeu_pd(p,
                   _mm256_add_pd(_mm256_loadu_pd(p), _mm256_cvtps_pd(_mm256_castps256_ps128(v))));
  _mm256_storeu_pd(
      p + 4, _mm256_add_pd(_mm256_loadu_pd(p + 4), _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1))));
}

// The three formulas of flame/variations_paper.cpp (the paper's appendix) over SLEEF's lanes.
Lanes sinusoidal(const Sleef& s, __m256 x, __m256 y, __m256, float w) {
  const __m256 ww = _mm256_set1_ps(w);
  return {_mm256_mul_ps(ww, s.sin(x)), _mm256_mul_ps(ww, s.sin(y))};
}
Lanes exponential(const Sleef& s, __m256 x, __m256 y, __m256, float w) {
  const __m256 k = _mm256_mul_ps(_mm256_set1_ps(w), s.exp(_mm256_sub_ps(x, _mm256_set1_ps(1))));
  const Sleef___m256_2 sc = s.sincos(_mm256_mul_ps(_mm256_set1_ps(std::numbers::pi_v<float>), y));
  return {_mm256_mul_ps(k, sc.y), _mm256_mul_ps(k, sc.x)};
}
// julian, power 5, dist 1: the branch trunc(|p|·Ψ), angle (φ + 2π·branch)/p, radius r^(d/p).
Lanes julian(const Sleef& s, __m256 x, __m256 y, __m256 u, float w) {
  constexpr float p = 5, d = 1;
  const __m256 branch = _mm256_round_ps(_mm256_mul_ps(_mm256_set1_ps(p), u), _MM_FROUND_TO_ZERO);
  const __m256 angle = _mm256_div_ps(
      _mm256_add_ps(s.atan2(y, x),
                    _mm256_mul_ps(_mm256_set1_ps(2 * std::numbers::pi_v<float>), branch)),
      _mm256_set1_ps(p));
  const Sleef___m256_2 sc = s.sincos(angle);
  const __m256 r2 = _mm256_add_ps(_mm256_mul_ps(x, x), _mm256_mul_ps(y, y));
  const __m256 k = _mm256_mul_ps(_mm256_set1_ps(w), s.pow(r2, _mm256_set1_ps(d / p / 2)));
  return {_mm256_mul_ps(k, sc.y), _mm256_mul_ps(k, sc.x)};
}

using Formula = Lanes (*)(const Sleef&, __m256, __m256, __m256, float);

void run_sleef(const Sleef& s, Formula f, Batch& b) {
  for (std::size_t i = 0; i < kN; i += 8) {
    const Lanes r = f(s, to_float(&b.x[i]), to_float(&b.y[i]), to_float(&b.u[i]), 0.5f);
    add_to(&b.ox[i], r.x);
    add_to(&b.oy[i], r.y);
  }
}

template <class F>
double ns_per_point(Batch& b, F run) {
  double best = 1e30;
  for (int round = 0; round < kRounds; ++round) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < kRepeats; ++r) run(b);
    const std::chrono::duration<double, std::nano> dt = std::chrono::steady_clock::now() - t0;
    best = std::min(best, dt.count() / (kRepeats * static_cast<double>(kN)));
  }
  return best;
}

// The largest |result − reference| over the batch, of one run from zeroed sums.
template <class F>
double deviation(Batch& b, F run, const std::vector<double>& rx, const std::vector<double>& ry) {
  std::fill(b.ox.begin(), b.ox.end(), 0.0);
  std::fill(b.oy.begin(), b.oy.end(), 0.0);
  run(b);
  double worst = 0;
  for (std::size_t i = 0; i < kN; ++i)
    worst = std::max({worst, std::abs(b.ox[i] - rx[i]), std::abs(b.oy[i] - ry[i])});
  return worst;
}

}  // namespace

int main() {
  if (cpu_level() < CpuLevel::avx2) {
    std::fprintf(stderr, "sleef_vs_vmath: this machine has no AVX2\n");
    return 2;
  }
  Batch b{std::vector<double>(kBatchStride), std::vector<double>(kBatchStride),
          std::vector<double>(kBatchStride), std::vector<double>(kBatchStride),
          std::vector<double>(kBatchStride)};
  Rng rng(7);
  for (std::size_t i = 0; i < kN; ++i) {
    b.x[i] = 3 * (2 * rng.uniform() - 1);
    b.y[i] = 3 * (2 * rng.uniform() - 1);
    b.u[i] = rng.uniform();
  }
  const Sleef avx2{Sleef_sinf8_u35avx2, Sleef_sincosf8_u35avx2, Sleef_atan2f8_u35avx2,
                   Sleef_expf8_u10avx2, Sleef_powf8_u10avx2};
  const Sleef avx{Sleef_sinf8_u35avx, Sleef_sincosf8_u35avx, Sleef_atan2f8_u35avx,
                  Sleef_expf8_u10avx, Sleef_powf8_u10avx};
  struct Row {
    const char* name;
    Formula sleef;
    std::vector<double> params;
  };
  const std::array<Row, 3> rows{Row{"sinusoidal", sinusoidal, {}},
                                Row{"exponential", exponential, {}}, Row{"julian", julian, {5, 1}}};
  std::printf(
      "# ns per point (best of %d rounds of %d batches of %zu points); max |difference| "
      "from the registry's double result\n",
      kRounds, kRepeats, kN);
  std::printf("%-12s %8s %8s %9s %8s   %9s %9s %9s\n", "variation", "ifsfx", "sleef", "sleef-avx",
              "libm", "d(ifsfx)", "d(sleef)", "d(avx)");
  for (const Row& row : rows) {
    const flame::Variation* v = flame::find_variation(row.name);
    const flame::detail::BatchVariation* batch =
        flame::detail::find_batch_variation(CpuLevel::avx2, row.name, flame::detail::LaneType::f32);
    const AffineMap identity{};
    const BatchTerm term{.w = 0.5, .params = row.params.data(), .pre = &identity, .u = b.u.data()};
    // The registry in double; julian's branch from the same draw as the batch forms' (u).
    std::vector<double> rx(kN), ry(kN);
    Rng fixed(0);  // drawn from by no variation here
    const auto registry = [&](Batch& bb) {
      for (std::size_t i = 0; i < kN; ++i) {
        const Point p{bb.x[i], bb.y[i]};
        if (row.name == std::string_view("julian")) {
          const double a =
              (std::atan2(p.y, p.x) + 2 * std::numbers::pi * std::trunc(5 * bb.u[i])) / 5;
          const double k = 0.5 * std::pow(p.x * p.x + p.y * p.y, 0.1);
          bb.ox[i] += k * std::cos(a);
          bb.oy[i] += k * std::sin(a);
          continue;
        }
        const Point q =
            v->function({.p = p, .w = 0.5, .params = row.params, .pre = &identity}, fixed);
        bb.ox[i] += q.x;
        bb.oy[i] += q.y;
      }
    };
    const auto ours = [&](Batch& bb) {
      batch->function(term, kN, bb.x.data(), bb.y.data(), bb.ox.data(), bb.oy.data());
    };
    const auto theirs = [&](Batch& bb) { run_sleef(avx2, row.sleef, bb); };
    const auto theirs_avx = [&](Batch& bb) { run_sleef(avx, row.sleef, bb); };
    std::fill(b.ox.begin(), b.ox.end(), 0.0);
    std::fill(b.oy.begin(), b.oy.end(), 0.0);
    registry(b);
    rx.assign(b.ox.begin(), b.ox.begin() + kN);
    ry.assign(b.oy.begin(), b.oy.begin() + kN);
    const double d_ours = deviation(b, ours, rx, ry), d_sleef = deviation(b, theirs, rx, ry),
                 d_avx = deviation(b, theirs_avx, rx, ry);
    std::printf("%-12s %8.2f %8.2f %9.2f %8.2f   %9.1e %9.1e %9.1e\n", row.name,
                ns_per_point(b, ours), ns_per_point(b, theirs), ns_per_point(b, theirs_avx),
                ns_per_point(b, registry), d_ours, d_sleef, d_avx);
  }
  return 0;
}
