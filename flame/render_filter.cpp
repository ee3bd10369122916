// SPDX-License-Identifier: Apache-2.0
// Step 3 of flame/render_tone.h: the spatial filter, the shapes flam3 offers (the textbook
// reconstruction filters: Wolberg, "Digital Image Warping"; Mitchell & Netravali 1988).
#include <cmath>
#include <numbers>
#include <numeric>
#include <string_view>

#include <fmt/format.h>

#include "flame/render_tone.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::flame {
namespace {

constexpr double kPi = std::numbers::pi;

double sinc(double x) {
  return x == 0 ? 1 : std::sin(kPi * x) / (kPi * x);
}

// Mitchell–Netravali cubic with parameters B, C.
double cubic(double x, double b, double c) {
  x = std::abs(x);
  if (x < 1)
    return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + 6 - 2 * b) / 6;
  if (x < 2)
    return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + 8 * b +
            24 * c) /
           6;
  return 0;
}

double bell(double x) {
  x = std::abs(x);
  if (x < 0.5) return 0.75 - x * x;
  if (x < 1.5) return 0.5 * (x - 1.5) * (x - 1.5);
  return 0;
}

struct Shape {
  std::string_view name;
  double support;  // the function is 0 beyond ±support
  double (*f)(double);
};

constexpr Shape kShapes[] = {
    {"gaussian", 1.5, [](double x) { return std::exp(-2 * x * x) * std::sqrt(2 / kPi); }},
    {"hermite", 1,
     [](double x) {
       x = std::abs(x);
       return x < 1 ? (2 * x - 3) * x * x + 1 : 0;
     }},
    {"box", 0.5, [](double x) { return std::abs(x) <= 0.5 ? 1.0 : 0.0; }},
    {"triangle", 1, [](double x) { return std::max(0.0, 1 - std::abs(x)); }},
    {"bell", 1.5, bell},
    {"quadratic", 1.5, bell},
    {"bspline", 2, [](double x) { return cubic(x, 1, 0); }},
    {"mitchell", 2, [](double x) { return cubic(x, 1.0 / 3, 1.0 / 3); }},
    {"catrom", 2, [](double x) { return cubic(x, 0, 0.5); }},
    {"lanczos3", 3, [](double x) { return std::abs(x) < 3 ? sinc(x) * sinc(x / 3) : 0; }},
    {"lanczos2", 2, [](double x) { return std::abs(x) < 2 ? sinc(x) * sinc(x / 2) : 0; }},
    {"blackman", 1,
     [](double x) { return 0.42 + 0.5 * std::cos(kPi * x) + 0.08 * std::cos(2 * kPi * x); }},
    {"hanning", 1, [](double x) { return 0.5 + 0.5 * std::cos(kPi * x); }},
    {"hamming", 1, [](double x) { return 0.54 + 0.46 * std::cos(kPi * x); }},
};

}  // namespace

SpatialKernel spatial_kernel(const std::string& shape, double radius, int ss) {
  const Shape* s = nullptr;
  for (const Shape& candidate : kShapes)
    if (candidate.name == shape) s = &candidate;
  if (s == nullptr)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("filter_shape: gaussian, hermite, box, triangle, bell, quadratic, "
                            "bspline, mitchell, catrom, lanczos3, lanczos2, blackman, hanning or "
                            "hamming is needed (got \"{}\")",
                            shape));
  SpatialKernel k;
  // The kernel spans 2·support·radius pixels, a whole number of bins whose parity is ss's, so
  // that it sits centred on the ss × ss bins of its pixel.
  const double span = 2 * s->support * ss * radius;
  k.width = static_cast<int>(span) + 1;
  if ((k.width ^ ss) & 1) ++k.width;
  if (!(span > 0) || k.width < ss) k.width = ss;
  k.gutter = (k.width - ss) / 2;
  k.taps.resize(static_cast<std::size_t>(k.width));
  const double adjust = span > 0 ? s->support * k.width / span : 0;
  for (int i = 0; i < k.width; ++i)
    k.taps[static_cast<std::size_t>(i)] =
        span > 0 ? s->f(((2.0 * i + 1) / k.width - 1) * adjust) : 1.0;
  const double sum = std::accumulate(k.taps.begin(), k.taps.end(), 0.0);
  for (double& t : k.taps) t /= sum;
  return k;
}

FlameHistogram spatial_filter(const FlameHistogram& bins, const SpatialKernel& kernel, int ss,
                              int width, int height, int threads, const CancelToken& cancel) {
  FlameHistogram out(width, height);
  const int n = kernel.width;
  parallel_rows(height, 16, threads, cancel, "spatial filter", [&](cv::Range rows) {
    std::vector<double> line(4 * static_cast<std::size_t>(bins.width));
    for (int i = rows.start; i < rows.end; ++i) {
      // Vertical pass into one line of bins, then the horizontal pass of each pixel.
      std::fill(line.begin(), line.end(), 0.0);
      for (int u = 0; u < n; ++u) {
        const double w = kernel.taps[static_cast<std::size_t>(u)];
        const double* src = bins.at(i * ss + u, 0);
        for (std::size_t k = 0; k < line.size(); ++k) line[k] += w * src[k];
      }
      for (int j = 0; j < width; ++j) {
        double* o = out.at(i, j);
        for (int v = 0; v < n; ++v) {
          const double w = kernel.taps[static_cast<std::size_t>(v)];
          const double* src = &line[4 * static_cast<std::size_t>(j * ss + v)];
          for (int k = 0; k < 4; ++k) o[k] += w * src[k];
        }
      }
    }
  });
  return out;
}

}  // namespace ifsfx::flame
