// SPDX-License-Identifier: Apache-2.0
// Steps 1, 2 and 4 of flame/render_tone.h: the log density, density estimation and the display.
#include "flame/render_tone.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

#include "flame/detail/density_kernel.h"
#include "ifs/cpu.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::flame {
namespace {

// The disc of one density-estimation radius: offsets and the weights of the spatial filter's
// Gaussian e^(−2x²) over its support x ∈ [0, 1.5] stretched to the radius, e^(−4.5·d²/r²),
// normalised to sum 1 (a radius below one bin keeps the bin to itself). flam3-render spreads a
// lone bin so (docs/flames.md, "Density estimation": its profile at estimator radii 9–60 is
// e^(−a·d²) with a·r² = 4.5 for r as kDeRadiusScale below says); Epanechnikov's 1 − d²/r²,
// used before, spread sparse points flatter than flam3 does. Row by row: each row of the disc
// is a run of consecutive dx (d² grows with |dx|), so that a bin's spreading clips a row once
// and adds along it, not tap by tap.
struct DeKernel {
  struct Row {
    int dy, dx0, n;     // taps dx0 … dx0 + n − 1 of row dy
    std::size_t first;  // their weights: w[first, first + n)
  };
  std::vector<Row> rows;
  std::vector<double> w;
  int reach = 0;
};

DeKernel de_kernel(double radius) {
  DeKernel k;
  const int reach = static_cast<int>(std::floor(radius));
  double sum = 0;
  for (int dy = -reach; dy <= reach; ++dy) {
    DeKernel::Row row{dy, 0, 0, k.w.size()};
    for (int dx = -reach; dx <= reach; ++dx) {
      const double d2 = static_cast<double>(dx * dx + dy * dy) / (radius * radius);
      if (d2 >= 1) continue;  // the centre, d = 0, is always in
      if (row.n == 0) row.dx0 = dx;
      ++row.n;
      const double w = std::exp(-4.5 * d2);
      k.w.push_back(w);
      sum += w;
    }
    if (row.n > 0) k.rows.push_back(row);
  }
  for (double& w : k.w) w /= sum;
  k.reach = reach;
  return k;
}

// The hits a bin's radius is chosen by: with ss > 1 bins per pixel side the bin's own count
// is ss² too small, so the counts of the surrounding pixel's worth of bins are summed.
double de_density(const FlameHistogram& h, int row, int col, int ss) {
  if (ss == 1) return h.at(row, col)[3];
  const int half = ss / 2;
  double sum = 0;
  for (int r = std::max(0, row - half); r <= std::min(h.height - 1, row + half); ++r)
    for (int c = std::max(0, col - half); c <= std::min(h.width - 1, col + half); ++c)
      sum += h.at(r, c)[3];
  const double side = 2 * half + 1;
  return sum * (ss * ss) / (side * side);
}

// Kernels by radius, quantised to 1/16 bin: a picture uses a few dozen.
class DeKernels {
 public:
  explicit DeKernels(double max_radius)
      : kernels_(static_cast<std::size_t>(std::ceil(max_radius * 16)) + 1) {}
  const DeKernel& operator()(double radius) {
    const auto key =
        std::min(static_cast<std::size_t>(std::lround(radius * 16)), kernels_.size() - 1);
    if (!kernels_[key]) kernels_[key] = de_kernel(std::max(static_cast<double>(key) / 16, 1e-3));
    return *kernels_[key];
  }

 private:
  std::vector<std::optional<DeKernel>> kernels_;
};

constexpr int kDeBand = 64;  // source rows per density-estimation band

// The radius of a bin of density n is kDeRadiusScale · estimator_radius / n^estimator_curve
// (held to [estimator_minimum, estimator_radius]): flam3-render's lone-bin profiles, read as
// above, give 1.04–1.10 times the plain formula at 22–1089 hits, and 1.1 brings 20 random
// genomes' SSIM and colour distance to flam3's pictures within 0.0024 and 0.1 (means) of
// flam3's own seed-to-seed values, from 0.0077 and 0.33 with 1 and Epanechnikov's kernel.
constexpr double kDeRadiusScale = 1.1;
// With supersampling (n then from de_density's window) flam3-render's lone bin spreads less:
// its profile's width (3σ, in pixels) at supersample 2 and 8, 13, 30, 100, 300 hits is 4.90,
// 4.28, 3.18, 2.10, 1.50, and 1.05 gives 5.06, 4.36, 3.18, 2.10, 1.50 where 1.1 gave 5.25,
// 4.46, 3.31, 2.19, 1.53; at supersample 3, 3.71, 3.10, 2.35, 1.35 against 1.05's 3.71, 3.07,
// 2.36, 1.36. The wider spread made sparse regions of supersampled flames brighter than
// flam3's (Fractorium's tyrantwave_base_forms 7: mean +1.3 levels, now +0.6).
constexpr double kDeRadiusScaleSupersampled = 1.05;

}  // namespace
}  // namespace ifsfx::flame

// p[k] += w·v[k] for the four channels, two at a time (GCC's generic vectors: SSE2 on x86-64,
// scalar code elsewhere; each lane the product and sum of the scalar loop). Left to itself, GCC
// vectorised the row across bins, with a transposing shuffle for every tap.
void ifsfx::detail::kernel_scalar::flame_spread_row(double* o, const double* w, int n,
                                                    const double* v) {
  using D2 = double __attribute__((vector_size(16)));
  D2 va, vb;
  std::memcpy(&va, v, sizeof va);
  std::memcpy(&vb, v + 2, sizeof vb);
  for (int i = 0; i < n; ++i, o += 4) {
    D2 a, b;
    std::memcpy(&a, o, sizeof a);
    std::memcpy(&b, o + 2, sizeof b);
    const D2 ww = {w[i], w[i]};
    a += ww * va;
    b += ww * vb;
    std::memcpy(o, &a, sizeof a);
    std::memcpy(o + 2, &b, sizeof b);
  }
}

namespace ifsfx::flame {

detail::SpreadRowFunction detail::spread_row_function(CpuLevel level) {
#if IFSFX_FLAME_X86_KERNELS
  // AVX-512 runs the AVX2 row: a bin is four doubles.
  if (level != CpuLevel::scalar) return ifsfx::detail::kernel_avx2::flame_spread_row;
#else
  (void)level;
#endif
  return ifsfx::detail::kernel_scalar::flame_spread_row;
}

namespace {

// The last few results of f(x) by x's bits, as a direct-mapped table: a bin's radius (a pow)
// depends only on its density and its log scale (a log1p) only on its hits, and both repeat
// from bin to bin (whole hits, a window's sum of them); pow and log1p were 3–5 % of a pack
// flame's command (perf, 27 Nov). The same x gives the same result: the bits do not change.
template <class T>
class Memo {
 public:
  template <class F>
  T operator()(double x, F&& f) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    Entry& e = entries_[(bits ^ (bits >> 21) ^ (bits >> 42)) % entries_.size()];
    if (!e.used || e.x != x) e = {true, x, f(x)};
    return e.y;
  }

 private:
  struct Entry {
    bool used = false;
    double x = 0;
    T y{};
  };
  std::array<Entry, 64> entries_{};
};

// Spreads the log-scaled bins of rows [r0, r1) into the rows `rows[y − origin]` (a row of the
// picture's width, 4 values a bin).
void spread_band(const FlameHistogram& h, const Filtering& f, int ss, const LogScale& scale, int r0,
                 int r1, int origin, double* const* rows) {
  const double max_r = f.estimator_radius * ss, min_r = f.estimator_minimum * ss;
  const double scale_r = ss > 1 ? kDeRadiusScaleSupersampled : kDeRadiusScale;
  DeKernels kernels(max_r);
  const detail::SpreadRowFunction spread_row = detail::spread_row_function(cpu_level());
  Memo<double> log_scaled;
  Memo<const DeKernel*> kernel_of;
  const auto kernel_of_density = [&](double d) {
    const double radius = std::max(min_r, scale_r * max_r / std::pow(d, f.estimator_curve));
    return &kernels(std::min(radius, max_r));
  };
  for (int row = r0; row < r1; ++row)
    for (int col = 0; col < h.width; ++col) {
      const double* in = h.at(row, col);
      if (!(in[3] > 0)) continue;
      const double ls = log_scaled(in[3], scale);
      const double v[4] = {in[0] * ls, in[1] * ls, in[2] * ls, in[3] * ls};
      // Each output bin takes one contribution from this bin, w·v, as tap by tap: the same sums.
      const DeKernel& kernel = *kernel_of(de_density(h, row, col, ss), kernel_of_density);
      for (const DeKernel::Row& r : kernel.rows) {
        const int y = row + r.dy;
        if (y < 0 || y >= h.height) continue;
        const int x0 = std::max(0, col + r.dx0), x1 = std::min(h.width, col + r.dx0 + r.n);
        const double* w = kernel.w.data() + r.first + (x0 - (col + r.dx0));
        if (x1 > x0) spread_row(rows[y - origin] + 4 * static_cast<std::size_t>(x0), w, x1 - x0, v);
      }
    }
}

}  // namespace

double LogScale::operator()(double a) const {
  return a > 0 ? k1 * std::log1p(k2 * a) / a : 0;
}

LogScale log_scale(const Flame& flame, int ss, double quality) {
  const Camera& cam = flame.camera;
  const double ppu = cam.scale * std::exp2(cam.zoom);
  const double area = cam.width * static_cast<double>(cam.height) / (ppu * ppu);
  const double q = quality * std::exp2(2 * cam.zoom);
  const double contrast = flame.tone.contrast;
  // 268/256: flam3's white, 268 of 256 levels before the gamma, kept for the same brightness.
  return {contrast * flame.tone.brightness * 268.0 / 256.0, ss * ss / (contrast * area * q)};
}

FlameHistogram density_estimate(const FlameHistogram& h, const Filtering& f, int ss,
                                const LogScale& scale, int threads, const CancelToken& cancel) {
  const int reach = static_cast<int>(std::floor(f.estimator_radius * ss));
  const int bands = (h.height + kDeBand - 1) / kDeBand;
  // Band b spreads rows [64b, 64b + 64) into rows 64b − reach … 64b + 64 + reach. Each band's
  // sums are its own, added in band order, so that they do not depend on the threads: a row
  // that an earlier band also reaches goes into a buffer of this band's, added to the picture
  // after all bands; the first band to reach a row spreads into the picture's row itself,
  // which starts at 0 (0 + p is p: the bits of the sums of buffers of every band before
  // 27 Nov, without their 2·reach rows a band of allocation, zeroing and adding).
  // (Without reach the renderer scales its histogram in place: the overload below.)
  const auto first_band = [&](int y) { return y < reach ? 0 : (y - reach) / kDeBand; };
  FlameHistogram out(h.width, h.height);
  std::vector<FlameHistogram> parts(static_cast<std::size_t>(bands));
  parallel_for(static_cast<std::size_t>(bands), threads, [&](std::size_t band, int) {
    cancel.check("density estimation");
    const int b = static_cast<int>(band);
    const int r0 = b * kDeBand, r1 = std::min(h.height, r0 + kDeBand);
    const int y0 = std::max(0, r0 - reach), y1 = std::min(h.height, r1 + reach);
    int own = y0;  // rows [y0, own) are an earlier band's too
    while (own < y1 && first_band(own) < b) ++own;
    parts[band] = FlameHistogram(h.width, own - y0);
    std::vector<double*> rows(static_cast<std::size_t>(y1 - y0));
    for (int y = y0; y < y1; ++y)
      rows[static_cast<std::size_t>(y - y0)] = y < own ? parts[band].at(y - y0, 0) : out.at(y, 0);
    spread_band(h, f, ss, scale, r0, r1, y0, rows.data());
  });
  for (int band = 0; band < bands; ++band) {
    const FlameHistogram& p = parts[static_cast<std::size_t>(band)];
    const int y0 = std::max(0, band * kDeBand - reach);
    for (int r = 0; r < p.height; ++r) {
      const double* src = p.at(r, 0);
      double* dst = out.at(y0 + r, 0);
      for (int i = 0; i < 4 * h.width; ++i) dst[i] += src[i];
    }
  }
  return out;
}

FlameHistogram density_estimate(FlameHistogram&& h, const Filtering& f, int ss,
                                const LogScale& scale, int threads, const CancelToken& cancel) {
  if (static_cast<int>(std::floor(f.estimator_radius * ss)) != 0)
    return density_estimate(static_cast<const FlameHistogram&>(h), f, ss, scale, threads, cancel);
  // Without reach spread_band's one tap has weight 1 (its kernel's only tap, normalised) and
  // adds v to a zero: out = v = in·ls(a) exactly, and 0 where a is 0 (a bin of no alpha has no
  // colour either: a hit's channels are its alpha × palette entries in [0, 1], rounded).
  const int bands = (h.height + kDeBand - 1) / kDeBand;
  parallel_for(static_cast<std::size_t>(bands), threads, [&](std::size_t band, int) {
    cancel.check("density estimation");
    const int r0 = static_cast<int>(band) * kDeBand, r1 = std::min(h.height, r0 + kDeBand);
    for (int row = r0; row < r1; ++row)
      for (int col = 0; col < h.width; ++col) {
        double* p = h.at(row, col);
        const double ls = p[3] > 0 ? scale(p[3]) : 0;
        for (int k = 0; k < 4; ++k) p[k] *= ls;
      }
  });
  return std::move(h);
}

}  // namespace ifsfx::flame
