// SPDX-License-Identifier: Apache-2.0
// The filter stage of `ifsfx filter` alone (no decode, no encode): one frame coloured through a
// fixed steal map (issue 5 target: ≥ 150 fps at 1920×1080, bilinear, on 2 cores), and the
// --animate drift stage at 1280×720 (target ≥ 30 fps), keyframe maps rebuilt on a worker while
// frames flow, counted as part of the stage's time.
//
//   build/bench/filter_bench
//   build/bench/filter_bench --benchmark_filter=fixed
#include <memory>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>

#include "engine/drift.h"
#include "engine/fractal_filter.h"
#include "engine/map_schedule.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"

namespace {

using namespace ifsfx;
using namespace ifsfx::engine;

// A frame with real structure (a smooth field plus noise), so caches see a natural image.
cv::Mat test_frame(cv::Size size) {
  cv::Mat frame(size, CV_8UC3);
  cv::randu(frame, cv::Scalar::all(0), cv::Scalar::all(255));
  return frame;
}

void fixed_map(benchmark::State& state, Interpolation interpolation) {
  const cv::Size size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const Ifs fern = load_ifs("barnsley-fern").ifs;
  const StealMap map = compute_steal_map(fern, default_colouring(fern.size()), size,
                                         {.sampling = {.quality = 8}, .exact = false});
  const PreparedStealMap table = prepare_filter(map, size, interpolation);
  const cv::Mat frame = test_frame(size);
  cv::Mat out;
  for (auto _ : state) {
    out = filter_frame(frame, table);
    benchmark::DoNotOptimize(out.data);
  }
  // Checked result: covered pixels come from the frame, the rest is the black background.
  if (out.size() != size || cv::countNonZero(map.coverage) == 0)
    state.SkipWithError("filter produced no image");
  state.SetItemsProcessed(state.iterations());
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_filter_fixed_map_bilinear(benchmark::State& state) {
  fixed_map(state, Interpolation::bilinear);
}
BENCHMARK(BM_filter_fixed_map_bilinear)
    ->Args({1920, 1080})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_filter_fixed_map_nearest(benchmark::State& state) {
  fixed_map(state, Interpolation::nearest);
}
BENCHMARK(BM_filter_fixed_map_nearest)
    ->Args({1920, 1080})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// --animate drift as `ifsfx filter` runs it: keyframes every K frames built on a worker from the
// drifted IFS, each frame a cross-fade of two remaps. Frames run at the nominal 30 fps clock for
// the drift, as fast as the stage allows.
void BM_filter_drift(benchmark::State& state) {
  const cv::Size size(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const int interval = static_cast<int>(state.range(2));
  const Ifs fern = load_ifs("barnsley-fern").ifs;
  const Ifs G = default_colouring(fern.size());
  StealMapOptions o;
  o.sampling.view = fit_view(attractor_bounds(fern), size, 0.05);
  o.sampling.quality = 4;
  o.exact = false;  // the chaos game at 4 points per pixel
  const DriftOptions drift_options{.amount = 0.05, .speed = 0.2};
  MapSchedule schedule(
      [&](std::int64_t k) {
        const Ifs now = drift(fern, static_cast<double>(k) * interval / 30.0, drift_options);
        return prepare_filter(compute_steal_map(now, G, size, o), size);
      },
      interval);
  const cv::Mat frame = test_frame(size);
  schedule.at(0);  // the start-up maps are not part of the steady state
  std::int64_t index = 0;
  cv::Mat out;
  for (auto _ : state) {
    const MapSchedule::Blend b = schedule.at(index++);
    out = filter_frame(frame, *b.from, *b.to, b.t);
    benchmark::DoNotOptimize(out.data);
  }
  if (out.size() != size) state.SkipWithError("filter produced no image");
  state.SetItemsProcessed(state.iterations());
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["stalls"] = static_cast<double>(schedule.stalls());
}
BENCHMARK(BM_filter_drift)
    ->Args({1280, 720, 30})
    ->Args({1280, 720, 60})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->MinTime(10);

}  // namespace

BENCHMARK_MAIN();
