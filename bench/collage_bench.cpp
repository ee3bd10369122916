// Collage fitting on 256×256 targets with N = 4 maps (issue: IoU ≥ 0.9 within 30 s on 2 cores):
// a leaf silhouette, a filled square and a filled equilateral triangle. Each benchmark times one
// whole fit (search, refinement, attractor rendering) and reports the attractor's IoU with the
// target, the collage theorem's upper bound and the measured Hausdorff distance as counters; it
// fails when the bound does not hold.
//   build-x/bench/collage_bench --benchmark_counters_tabular=true
#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgproc.hpp>

#include "collage/fit.h"
#include "collage/target.h"

namespace {

using namespace ifsfx;

constexpr int kSide = 256;

// A leaf, drawn here from its own outline (no image file needed): an ovate blade along the y
// axis from base (0) to tip (1), half-width w(t) = 0.36 sin(π t)^0.7 (1 − 0.45 t), with a
// shallow notch at the base and a stem. The polygon is written by this function and is in the
// public domain.
cv::Mat leaf() {
  cv::Mat image(kSide, kSide, CV_8UC1, cv::Scalar(255));  // dark shape on light ground
  std::vector<cv::Point> outline;
  const int steps = 200;
  auto to_pixel = [](double x, double y) {
    // Tilt the leaf by 25° and fit it in the frame.
    const double a = 25 * std::numbers::pi / 180;
    const double u = x * std::cos(a) - (y - 0.5) * std::sin(a);
    const double v = x * std::sin(a) + (y - 0.5) * std::cos(a);
    return cv::Point(static_cast<int>(std::lround(kSide * (0.5 + 0.8 * u))),
                     static_cast<int>(std::lround(kSide * (0.5 - 0.8 * v))));
  };
  auto half_width = [](double t) {
    return 0.36 * std::pow(std::sin(std::numbers::pi * t), 0.7) * (1 - 0.45 * t);
  };
  for (int i = 0; i <= steps; ++i) {  // right edge, base to tip
    const double t = static_cast<double>(i) / steps;
    outline.push_back(to_pixel(half_width(t), t));
  }
  for (int i = steps; i >= 0; --i) {  // left edge, tip to base
    const double t = static_cast<double>(i) / steps;
    outline.push_back(to_pixel(-half_width(t), t));
  }
  outline.push_back(to_pixel(0, 0.04));  // the notch where the stem joins
  cv::fillPoly(image, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(0), cv::LINE_AA);
  cv::line(image, to_pixel(0, 0.06), to_pixel(0, -0.14), cv::Scalar(0), 5, cv::LINE_AA);
  return image;
}

cv::Mat square() {
  cv::Mat image(kSide, kSide, CV_8UC1, cv::Scalar(255));
  image(cv::Rect(32, 32, kSide - 64, kSide - 64)).setTo(0);
  return image;
}

cv::Mat triangle() {
  cv::Mat image(kSide, kSide, CV_8UC1, cv::Scalar(255));
  const double side = kSide - 32, h = side * std::sqrt(3.0) / 2;
  const std::vector<cv::Point> corners = {{16, static_cast<int>(kSide / 2 + h / 2)},
                                          {kSide - 16, static_cast<int>(kSide / 2 + h / 2)},
                                          {kSide / 2, static_cast<int>(kSide / 2 - h / 2)}};
  cv::fillPoly(image, std::vector<std::vector<cv::Point>>{corners}, cv::Scalar(0), cv::LINE_AA);
  return image;
}

void fit_target(benchmark::State& state, cv::Mat (*make)()) {
  const cv::Mat raster = collage::working_raster(collage::shape_mask(make()),
                                                 {.size = static_cast<int>(state.range(0))});
  collage::FitOptions options;
  options.maps = 4;
  options.max_seconds = 30;
  options.threads = 2;
  collage::FitResult result;
  for (auto _ : state) result = collage::fit(raster, options);
  const auto& r = result.report;
  state.counters["iou"] = r.iou;
  state.counters["collage_iou"] = r.collage_iou;
  state.counters["h_collage"] = r.collage_distance;
  state.counters["s"] = r.contraction;
  state.counters["bound"] = r.upper_bound;
  state.counters["h_measured"] = r.hausdorff;
  state.counters["evaluations"] = static_cast<double>(result.evaluations);
  state.counters["capped"] = result.time_capped ? 1 : 0;
  if (!(r.hausdorff <= r.upper_bound)) state.SkipWithError("measured h(L, A) exceeds the bound");
}

BENCHMARK_CAPTURE(fit_target, leaf, leaf)
    ->Arg(128)
    ->Arg(256)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(fit_target, square, square)
    ->Arg(128)
    ->Arg(256)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(fit_target, triangle, triangle)
    ->Arg(128)
    ->Arg(256)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
