// SPDX-License-Identifier: Apache-2.0
// Fractal tops and colour stealing (issue 3 targets, 2-core machine):
//   chaos-game tops + stealing ≥ 150 Mpts/s per core; exact steal map 1920×1080 fern ≤ 250 ms on
//   2 cores; apply of a 1080p map to a 1080p frame ≥ 150 frames/s on 2 cores (bilinear);
//   issue 14: the prepared apply ≥ 450 frames/s at 1080p and ≥ 110 at 2160p on 2 cores.
// Run: build/bench/steal_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "ifs/detail/address_raster.h"
#include "ifs/steal_map.h"

namespace {

using namespace ifsfx;

Ifs fern() {
  Ifs t;
  t.name = "fern";
  t.maps = {{0, 0, 0, 0.16, 0, 0},
            {0.85, 0.04, -0.04, 0.85, 0, 1.6},
            {0.2, -0.26, 0.23, 0.22, 0, 1.6},
            {-0.15, 0.28, 0.26, 0.24, 0, 0.44}};
  t.probabilities = {0.01, 0.85, 0.07, 0.07};
  return t;
}

const cv::Size kHd(1920, 1080);

void check(bool ok, const char* what) {
  if (!ok) throw std::runtime_error(what);
}

// The chaos-game tops kernel alone (64-bit keys, largest wins), 16 points per pixel, no
// coverage policy. Reported per thread: Mpts/s per core.
void BM_chaos_tops_kernel(benchmark::State& state) {
  const Ifs F = fern();
  const int threads = static_cast<int>(state.range(0));
  const Viewport vp{fit_view(attractor_bounds(F), kHd), kHd};
  std::uint64_t points = 0;
  for (auto _ : state) {
    detail::ChaosTopsStats stats;
    const auto tops = detail::chaos_tops(
        F, vp, {.quality = 16, .threads = threads, .grow = false, .fill = false}, &stats);
    check(stats.hit > 100000, "fern hits too few pixels");
    points += stats.points;
  }
  state.counters["Mpts/s/core"] =
      benchmark::Counter(static_cast<double>(points) / 1e6 / threads, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_chaos_tops_kernel)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole chaos-game steal map (tops + stealing + coverage policy), 1920×1080 fern.
void BM_chaos_steal_map(benchmark::State& state) {
  const Ifs F = fern(), G = default_colouring(4);
  const int threads = static_cast<int>(state.range(0));
  std::uint64_t points = 0;
  for (auto _ : state) {
    StealMapStats stats;
    const StealMap map = compute_steal_map(
        F, G, kHd, {.sampling = {.quality = 16, .threads = threads}, .exact = false}, &stats);
    check(stats.coverage > 0.05, "fern covers too little");
    points += stats.points;
  }
  state.counters["Mpts/s/core"] =
      benchmark::Counter(static_cast<double>(points) / 1e6 / threads, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_chaos_steal_map)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The exact steal map (per-pixel descent), 1920×1080 fern.
void BM_exact_steal_map(benchmark::State& state) {
  const Ifs F = fern(), G = default_colouring(4);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const StealMap map =
        compute_steal_map(F, G, kHd, {.sampling = {.threads = threads}, .exact = true});
    check(cv::countNonZero(map.coverage) > 100000, "fern covers too little");
  }
}
BENCHMARK(BM_exact_steal_map)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// apply of a map to a BGR frame of its size, bilinear, prepared once (the video filter's path):
// 1920×1080 and 3840×2160 (issue 14 targets on 2 cores: ≥ 450 and ≥ 110 frames/s).
void BM_apply_prepared(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  const cv::Size size(static_cast<int>(state.range(1)), static_cast<int>(state.range(2)));
  const StealMap map = compute_steal_map(fern(), default_colouring(4), size,
                                         {.sampling = {.quality = 4}, .exact = false});
  cv::Mat frame(size, CV_8UC3);
  cv::randu(frame, 0, 256);
  const PreparedStealMap prepared = prepare_apply(map, frame.size(), {.threads = threads});
  cv::Mat out;
  for (auto _ : state) {
    apply(prepared, frame, out);
    benchmark::DoNotOptimize(out.data);
  }
  check(out.size() == size, "wrong output size");
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_apply_prepared)
    ->ArgNames({"threads", "w", "h"})
    ->Args({1, 1920, 1080})
    ->Args({2, 1920, 1080})
    ->Args({1, 3840, 2160})
    ->Args({2, 3840, 2160})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The reference: one cv::remap of the same prepared tables on OpenCV's own thread pool, the
// path apply took before the compact table (issue 14: 278 frames/s on one thread, 285 on two).
void BM_cv_remap_prepared(benchmark::State& state) {
  const cv::Size size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const StealMap map = compute_steal_map(fern(), default_colouring(4), size,
                                         {.sampling = {.quality = 4}, .exact = false});
  cv::Mat frame(size, CV_8UC3);
  cv::randu(frame, 0, 256);
  const PreparedStealMap prepared = prepare_apply(map, frame.size());
  cv::Mat out;
  for (auto _ : state) {
    cv::remap(frame, out, prepared.xy, prepared.frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    benchmark::DoNotOptimize(out.data);
  }
  cv::Mat ours;
  apply(prepared, frame, ours);
  check(cv::norm(out, ours, cv::NORM_INF) == 0, "apply differs from cv::remap");
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_cv_remap_prepared)
    ->ArgNames({"w", "h"})
    ->Args({1920, 1080})
    ->Args({3840, 2160})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same through apply(map, frame), preparing the remap tables every call.
void BM_apply_unprepared_1080p(benchmark::State& state) {
  const StealMap map = compute_steal_map(fern(), default_colouring(4), kHd,
                                         {.sampling = {.quality = 4}, .exact = false});
  cv::Mat frame(kHd, CV_8UC3);
  cv::randu(frame, 0, 256);
  for (auto _ : state) benchmark::DoNotOptimize(apply(map, frame, {.threads = 2}).data);
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_apply_unprepared_1080p)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
