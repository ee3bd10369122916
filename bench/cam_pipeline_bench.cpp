// SPDX-License-Identifier: Apache-2.0
// The live path of `ifsfx cam` without a camera: a synthetic source paced at 1280×720, 30 fps
// (frames "captured" in real time whether read or not, newest-frame-wins like a V4L2 driver with
// few buffers) through the fractal filter into a null sink, for a fixed run of real time.
// Reported per run: sustained fps, % of frames dropped, capture-to-output latency (mean, p95,
// max, in ms and in frame intervals), and the dequeue-to-output share. Targets (issue 6): 30 fps
// sustained on 2 cores, < 1% dropped, latency ≤ 2 frame intervals.
//
//   build/bench/cam_pipeline_bench                      # fixed map and drift, 10 s each
//   build/bench/cam_pipeline_bench --benchmark_filter=fixed
#include <memory>

#include <benchmark/benchmark.h>

#include "engine/camera_drift.h"
#include "engine/fractal_filter.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "video/camera_pipeline.h"
#include "video/camera_synthetic.h"

namespace {

using namespace ifsfx;
using namespace ifsfx::video;
using namespace ifsfx::engine;

constexpr double kFps = 30;
constexpr int kSeconds = 10;
const cv::Size kSize(1280, 720);

class NullSink final : public FrameSink {
 public:
  void write(const Frame& frame) override { checksum_ += frame.image.data[0]; }
  void close() override {}
  std::string name() const override { return "null"; }

 private:
  std::uint64_t checksum_ = 0;
};

void report(benchmark::State& state, const CameraStats& s) {
  const double interval = 1 / kFps;
  state.counters["fps"] = s.fps();
  state.counters["dropped_%"] = 100 * s.drop_fraction();
  state.counters["latency_ms"] = 1e3 * s.latency_mean;
  state.counters["latency_p95_ms"] = 1e3 * s.latency_p95;
  state.counters["latency_max_ms"] = 1e3 * s.latency_max;
  state.counters["latency_p95_frames"] = s.latency_p95 / interval;
  state.counters["process_ms"] = 1e3 * s.process_mean;
  state.counters["frames"] = static_cast<double>(s.frames);
  if (s.frames == 0) state.SkipWithError("no frames");
}

// The steal map of the default preset of `ifsfx cam`, coloured by the default tiling.
struct Setup {
  Ifs F = load_ifs("sierpinski-triangle").ifs;
  Ifs G = default_colouring(F.size());
};

void BM_cam_fixed_map(benchmark::State& state) {
  const Setup setup;
  const PreparedStealMap table =
      prepare_filter(compute_steal_map(setup.F, setup.G, kSize, {}), kSize);
  for (auto _ : state) {
    SyntheticCamera camera({.size = kSize, .fps = kFps});
    NullSink sink;
    const CameraStats s =
        run_camera(camera, [&](const Frame& f) { return filter_frame(f.image, table); }, {&sink},
                   {.max_frames = static_cast<std::int64_t>(kSeconds * kFps)});
    report(state, s);
  }
}
BENCHMARK(BM_cam_fixed_map)
    ->Name("cam/fixed_map/1280x720@30")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

// `ifsfx cam --animate drift`: maps rebuilt on a worker as fast as it goes, faded in, never
// waited for (engine/camera_drift.h). `maps` counts the maps built during the run.
void BM_cam_drift(benchmark::State& state) {
  const Setup setup;
  for (auto _ : state) {
    LiveDriftOptions o;
    o.drift = {.amount = 0.05, .speed = 0.2, .seed = 1};
    LiveDrift live(setup.F, setup.G, kSize, o);
    SyntheticCamera camera({.size = kSize, .fps = kFps});
    NullSink sink;
    const CameraStats s =
        run_camera(camera, [&](const Frame& f) { return live.filter(f.image, f.timestamp); },
                   {&sink}, {.max_frames = static_cast<std::int64_t>(kSeconds * kFps)});
    report(state, s);
    state.counters["maps"] = static_cast<double>(live.maps_built());
  }
}
BENCHMARK(BM_cam_drift)
    ->Name("cam/drift/1280x720@30")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
