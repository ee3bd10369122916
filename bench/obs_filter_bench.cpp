// SPDX-License-Identifier: Apache-2.0
// The OBS filter's live path without OBS: a synthetic 1280×720 NV12 webcam at 30 fps (BT.709
// limited range) through plugins/obs's FilterWorker, called as
// OBS's video thread calls the filter — once per frame interval, never waiting. Per mode (fixed
// map, drift): frames whose picture was never shown (dropped), frames that showed a picture again
// (repeated), a frame's latency from reaching the filter to its picture being ready (p50, p95,
// max) and to its being shown (one frame later by design), and the time OBS's thread spends in
// the filter, and the process's CPU time per picture shown (the worker's and the map builds').
// Target (issue 33): 0 dropped, p95 ready latency ≤ 33 ms, on 2 cores.
//
//   build/release/bench/obs_filter_bench [SECONDS [KEYFRAME_INTERVAL]]   # default 10 s, 12
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <media-io/video-io.h>

#include "engine/drawing.h"
#include "engine/drift.h"
#include "ifs/parallel.h"
#include "ifs/sampling.h"
#include "ifs/steal_map.h"
#include "plugins/obs/filter_worker.h"
#include "video/camera_synthetic.h"

namespace {

using namespace ifsfx;
using namespace ifsfx::obs;
using Ms = std::chrono::duration<double, std::milli>;

constexpr double kFps = 30;
const cv::Size kSize(1280, 720);

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

// CPU seconds of the whole process (every thread: the worker, the map builds).
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

std::string load() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// The camera's frames as NV12 planes, BT.709 limited range (what OBS gives for a webcam).
struct Webcam {
  YuvMatrix yuv;
  std::vector<std::vector<cv::Mat>> frames;
  Webcam() {
    video_format_get_parameters(VIDEO_CS_709, VIDEO_RANGE_PARTIAL, yuv.matrix.data(),
                                yuv.range_min.data(), yuv.range_max.data());
    const video::SyntheticCamera camera({.size = kSize, .fps = kFps, .patterns = 30});
    for (int k = 0; k < 30; ++k) {
      std::vector<cv::Mat> planes = {cv::Mat(kSize, CV_8UC1), cv::Mat(kSize / 2, CV_8UC2)};
      from_engine(camera.pattern(k), PixelFormat::nv12, yuv, planes);
      frames.push_back(planes);
    }
  }
};

// Wall and CPU milliseconds (the whole process: nothing else of it runs then) of the fastest of
// `times` calls of fn: the quiet cost, without the load's noise.
struct Cost {
  double wall = 1e300, cpu = 0;
};
template <typename Fn>
Cost best_of(int times, Fn&& fn) {
  Cost best;
  for (int i = 0; i < times; ++i) {
    const double c0 = cpu_seconds();
    const auto t0 = Clock::now();
    fn();
    const double wall = Ms(Clock::now() - t0).count();
    if (wall < best.wall) best = {wall, 1e3 * (cpu_seconds() - c0)};
  }
  return best;
}

std::string str(const Cost& c) {
  return fmt::format("{:.1f} ({:.1f} CPU)", c.wall, c.cpu);
}

// Where a picture's time goes, each part alone on an idle worker: the colour conversions, the
// filter through one map and through a cross-fade of two, and one drift keyframe's build (the
// engine's builder: drift, steal map, prepared table) on one thread and on all.
void breakdown(const PluginSettings& drift_settings, const Webcam& cam) {
  engine::FractalEngine engine(drift_settings.engine);
  const engine::FractalSettings& s = engine.settings();
  StealMapOptions map_options = engine.map_options();
  map_options = engine::with_fixed_view(engine.drawing(), kSize, map_options);
  StealMap map;
  const auto build = [&](int threads, double seconds) {
    map_options.sampling.threads = threads;
    map = engine::steal_map(engine::drift(engine.drawing(), seconds, engine.drift_options()),
                            engine.colouring(), kSize, map_options);
    return engine::prepare_filter(map, kSize, s.interpolation, threads);
  };
  const PreparedStealMap a = build(1, 0), b = build(1, 0.4);
  cv::Mat bgr, out;
  std::vector<cv::Mat> planes = cam.frames[0];
  const Cost in =
      best_of(10, [&] { bgr = to_engine(PixelFormat::nv12, cam.frames[0], cam.yuv, kSize); });
  const Cost back = best_of(10, [&] { from_engine(bgr, PixelFormat::nv12, cam.yuv, planes); });
  engine::FilterOptions one = engine.filter_options();
  std::string filters;
  for (const int threads : {1, 0}) {
    one.threads = threads;
    filters += fmt::format(
        "\n  {} thread(s): filter one map {}, cross-fade of two {}, drift keyframe build {} of "
        "which the prepared table {}",
        resolve_threads(threads), str(best_of(10, [&] { engine::filter_frame(bgr, a, one, out); })),
        str(best_of(10, [&] { engine::filter_frame(bgr, a, b, 0.5, one, out); })),
        str(best_of(3, [&] { build(threads, 0.8); })),
        str(best_of(3, [&] { engine::prepare_filter(map, kSize, s.interpolation, threads); })));
  }
  fmt::print("where the time goes (ms, fastest of 10, alone): NV12 in {}, out {}{}; load {}\n",
             str(in), str(back), filters, load());
}

// The picture-ready latencies of the frames shown, by the frame's phase within its keyframe
// interval (frame mod K): a keyframe build that slows the pictures shows as slow phases.
void by_phase(const std::vector<std::pair<std::int64_t, double>>& ready, int interval) {
  std::string line;
  for (int phase = 0; phase < interval; ++phase) {
    std::vector<double> v;
    int late = 0;
    for (const auto& [frame, ms] : ready)
      if (frame % interval == phase) {
        v.push_back(ms);
        late += ms > 1e3 / kFps;
      }
    line += fmt::format(" {}:{:.0f}/{:.0f}{}", phase, percentile(v, 0.5), percentile(v, 1),
                        late > 0 ? fmt::format("({} late)", late) : "");
  }
  fmt::print("  picture ready by phase (frame mod {}: p50/max ms):{}\n", interval, line);
}

void run(const char* name, const PluginSettings& settings, const Webcam& cam, double seconds,
         int keyframe_interval) {
  FilterWorker worker(kFps);
  worker.configure(settings);
  FrameData frame{.format = PixelFormat::nv12, .size = kSize, .yuv = cam.yuv};
  frame.planes = {cv::Mat(kSize, CV_8UC1), cv::Mat(kSize / 2, CV_8UC2)};
  const auto interval = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / kFps));
  const auto start = Clock::now();
  std::vector<double> ready, shown_after, in_filter;
  std::vector<std::pair<std::int64_t, double>> ready_of_frame;
  std::set<std::uint64_t> shown;
  std::int64_t measured = 0, k = 0;
  std::uint64_t first = 0;
  bool warm = false;
  double cpu_start = 0;
  for (;; ++k) {
    std::this_thread::sleep_until(start + k * interval);
    for (int i = 0; i < 2; ++i)
      cam.frames[static_cast<std::size_t>(k % 30)][static_cast<std::size_t>(i)].copyTo(
          frame.planes[static_cast<std::size_t>(i)]);
    frame.timestamp = static_cast<std::uint64_t>(k) * static_cast<std::uint64_t>(interval.count());
    const auto t0 = Clock::now();
    const Shown s = worker.exchange(frame);
    const auto t1 = Clock::now();
    if (!warm) {  // the maps are being built: not measured, nor the first picture (of a frame
                  // that waited for them)
      warm = s.written;
      first = s.timestamp;
      if (warm) fmt::print("{}: maps ready after {:.0f} ms\n", name, Ms(t1 - start).count());
      cpu_start = cpu_seconds();
      continue;
    }
    ++measured;
    in_filter.push_back(Ms(t1 - t0).count());
    if (s.timestamp != first && shown.insert(s.timestamp).second) {
      ready.push_back(Ms(s.finished - s.submitted).count());
      ready_of_frame.emplace_back(static_cast<std::int64_t>(s.timestamp / interval.count()),
                                  ready.back());
      shown_after.push_back(Ms(t0 - s.submitted).count());
    }
    if (measured >= static_cast<std::int64_t>(seconds * kFps)) break;
  }
  const double cpu_per_picture = 1e3 * (cpu_seconds() - cpu_start) /
                                 static_cast<double>(std::max<std::size_t>(shown.size(), 1));
  const auto never_shown = measured - static_cast<std::int64_t>(shown.size());
  fmt::print(
      "{}: {} frames, {} dropped (never shown), {} repeated; picture ready p50 {:.1f} ms, p95 "
      "{:.1f}, max {:.1f}; shown p50 {:.1f} ms, p95 {:.1f}; in OBS's thread p50 {:.2f} ms, p95 "
      "{:.2f}, max {:.2f}; CPU {:.1f} ms per picture shown (all threads); load {}\n",
      name, measured, never_shown, worker.stats().repeated, percentile(ready, 0.5),
      percentile(ready, 0.95), percentile(ready, 1), percentile(shown_after, 0.5),
      percentile(shown_after, 0.95), percentile(in_filter, 0.5), percentile(in_filter, 0.95),
      percentile(in_filter, 1), cpu_per_picture, load());
  if (settings.engine.animate != engine::Animate::none) by_phase(ready_of_frame, keyframe_interval);
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 10;
  const int interval = argc > 2 ? std::stoi(argv[2]) : 12;
  const Webcam cam;
  PropertyValues values;  // the filter's defaults: sierpinski-triangle, as `ifsfx cam`
  run("fixed/1280x720@30 nv12", settings_of(values), cam, seconds, interval);
  values.animate = "drift";
  values.keyframe_interval = interval;
  run(fmt::format("drift/1280x720@30 nv12, a map every {} frames", interval).c_str(),
      settings_of(values), cam, seconds, interval);
  breakdown(settings_of(values), cam);
  return 0;
}
