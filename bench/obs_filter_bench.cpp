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

void run(const char* name, const PluginSettings& settings, const Webcam& cam, double seconds) {
  FilterWorker worker(kFps);
  worker.configure(settings);
  FrameData frame{.format = PixelFormat::nv12, .size = kSize, .yuv = cam.yuv};
  frame.planes = {cv::Mat(kSize, CV_8UC1), cv::Mat(kSize / 2, CV_8UC2)};
  const auto interval = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 / kFps));
  const auto start = Clock::now();
  std::vector<double> ready, shown_after, in_filter;
  std::set<std::uint64_t> shown;
  std::int64_t measured = 0, k = 0;
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
    if (!warm) {  // the maps are being built: not measured
      warm = s.written;
      if (warm) fmt::print("{}: maps ready after {:.0f} ms\n", name, Ms(t1 - start).count());
      cpu_start = cpu_seconds();
      continue;
    }
    ++measured;
    in_filter.push_back(Ms(t1 - t0).count());
    if (shown.insert(s.timestamp).second) {
      ready.push_back(Ms(s.finished - s.submitted).count());
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
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::stod(argv[1]) : 10;
  const int interval = argc > 2 ? std::stoi(argv[2]) : 12;
  const Webcam cam;
  PropertyValues values;  // the filter's defaults: sierpinski-triangle, as `ifsfx cam`
  run("fixed/1280x720@30 nv12", settings_of(values), cam, seconds);
  values.animate = "drift";
  values.keyframe_interval = interval;
  run(fmt::format("drift/1280x720@30 nv12, a map every {} frames", interval).c_str(),
      settings_of(values), cam, seconds);
  return 0;
}
