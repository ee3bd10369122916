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

#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"
#include "video/camera_pipeline.h"
#include "video/camera_synthetic.h"
#include "video/drift.h"
#include "video/fractal_filter.h"
#include "video/map_schedule.h"

namespace {

using namespace ifsfx;
using namespace ifsfx::video;

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

void report(benchmark::State& state, const CameraStats& s, std::int64_t stalls) {
  const double interval = 1 / kFps;
  state.counters["fps"] = s.fps();
  state.counters["dropped_%"] = 100 * s.drop_fraction();
  state.counters["latency_ms"] = 1e3 * s.latency_mean;
  state.counters["latency_p95_ms"] = 1e3 * s.latency_p95;
  state.counters["latency_max_ms"] = 1e3 * s.latency_max;
  state.counters["latency_p95_frames"] = s.latency_p95 / interval;
  state.counters["process_ms"] = 1e3 * s.process_mean;
  state.counters["frames"] = static_cast<double>(s.frames);
  state.counters["map_stalls"] = static_cast<double>(stalls);
  if (s.frames == 0) state.SkipWithError("no frames");
}

// The steal map of the default preset of `ifsfx cam`, coloured by the default tiling.
struct Setup {
  Ifs F = load_ifs("sierpinski-triangle").ifs;
  Ifs G = default_colouring(F.size());
};

void BM_cam_fixed_map(benchmark::State& state) {
  const Setup setup;
  const RemapTable table = make_remap_table(compute_steal_map(setup.F, setup.G, kSize, {}), kSize);
  for (auto _ : state) {
    SyntheticCamera camera({.size = kSize, .fps = kFps});
    NullSink sink;
    const CameraStats s =
        run_camera(camera, [&](const Frame& f) { return filter_frame(f.image, table); }, {&sink},
                   {.max_frames = static_cast<std::int64_t>(kSeconds * kFps)});
    report(state, s, 0);
  }
}
BENCHMARK(BM_cam_fixed_map)
    ->Name("cam/fixed_map/1280x720@30")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

void BM_cam_drift(benchmark::State& state) {
  const Setup setup;
  const int interval = 12;  // `ifsfx cam --animate drift` default keyframe interval
  StealMapOptions o;
  o.view = fit_view(attractor_bounds(setup.F, 1), kSize, 0.05);
  const DriftOptions drift{.amount = 0.05, .speed = 0.2, .seed = 1};
  for (auto _ : state) {
    MapSchedule schedule(
        [&](std::int64_t k) {
          const Ifs now = video::drift(setup.F, static_cast<double>(k) * interval / kFps, drift);
          return make_remap_table(compute_steal_map(now, setup.G, kSize, o), kSize);
        },
        interval);
    schedule.at(0);  // the first maps are built before the camera starts, as `ifsfx cam` does
    std::int64_t clock = 0;
    SyntheticCamera camera({.size = kSize, .fps = kFps});
    NullSink sink;
    const CameraStats s =
        run_camera(camera,
                   [&](const Frame& f) {
                     const MapSchedule::Blend b = schedule.at(clock++);
                     return filter_frame(f.image, *b.from, *b.to, b.t);
                   },
                   {&sink}, {.max_frames = static_cast<std::int64_t>(kSeconds * kFps)});
    report(state, s, schedule.stalls());
  }
}
BENCHMARK(BM_cam_drift)
    ->Name("cam/drift/1280x720@30")
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
