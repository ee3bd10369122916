// SPDX-License-Identifier: Apache-2.0
// The live loop of `ifsfx cam`: newest frame from a live source → filter → sinks, one frame at a
// time, measuring what a live view is judged by: sustained frame rate, frames dropped, and
// capture-to-output latency. Single-threaded on purpose: with a newest-frame source, a frame is
// never queued behind another, so latency stays at about one filter time; the filter itself
// (a steal-map remap, paper §6) uses the cores.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "video/camera_source.h"
#include "video/frame_io.h"

namespace ifsfx::video {

struct CameraStats {
  std::int64_t frames = 0;   // frames filtered and written to every sink
  std::int64_t dropped = 0;  // frames the source captured but the loop never saw
  double seconds = 0;        // from the first frame read to the last frame out
  // Seconds from capture (Frame::timestamp on the source's clock) to the moment every sink has the
  // frame: mean, 95th percentile and worst.
  double latency_mean = 0, latency_p95 = 0, latency_max = 0;
  // Seconds from read() returning (the frame dequeued and converted) to output: the filter's and
  // the sinks' share of the latency.
  double process_mean = 0;

  // Frames per second over the run (intervals between frames out).
  double fps() const { return frames > 1 && seconds > 0 ? (frames - 1) / seconds : 0; }
  // Dropped frames as a fraction of all frames captured.
  double drop_fraction() const {
    return frames + dropped > 0 ? static_cast<double>(dropped) / (frames + dropped) : 0;
  }
};

struct CameraLoopOptions {
  std::int64_t max_frames = 0;              // stop after this many frames out; 0 = no limit
  const std::atomic<bool>* stop = nullptr;  // checked between frames (Ctrl-C, another thread)
};

// The image to show for a frame (a steal-map remap, or the frame itself).
using CameraFilter = std::function<cv::Mat(const Frame& frame)>;
// Called once per frame after the sinks, with the filtered frame and the stats so far; return
// false to stop (the window's quit key).
using CameraObserver = std::function<bool(const Frame& filtered, const CameraStats& stats)>;

// Runs the loop until max_frames, the stop flag, the observer, or the end of the source: each is
// the ordinary end of a live session, and every sink is closed (a recording is finalised and put
// in place). When the loop ends by an error, every sink is abandoned instead (FrameSink::abandon:
// a recording is kept as a playable partial movie beside its target) and the error is rethrown
// (a close that fails as well is not allowed to hide the first error). Returns the stats.
//   CameraStats s = run_camera(camera, [&](const Frame& f) { return apply(map, f.image); },
//                              {&webcam, &recording}, {.max_frames = 300});
CameraStats run_camera(LiveSource& source, const CameraFilter& filter,
                       const std::vector<FrameSink*>& sinks, const CameraLoopOptions& options = {},
                       const CameraObserver& observer = {});

}  // namespace ifsfx::video
