// SPDX-License-Identifier: Apache-2.0
// The OBS filter's worker (docs/design.md §10, OBS): OBS calls an async filter on its video
// thread, which must never wait for a fractal. exchange() copies the frame for the worker —
// replacing one the worker has not started, which is then dropped, never queued — and writes the
// newest finished picture into the frame. So a frame's picture is shown at the next frame (one
// frame of lag), a slow picture is repeated, and OBS never stalls.
//
// New settings are built beside the maps in use (a preset's steal map can take a second): frames
// keep their last good maps until the new ones are ready, and settings that fail keep them for
// good, their message in status(). Free of libobs: tests and the bench drive it directly.
//
//   FilterWorker worker(30);
//   worker.configure(settings);
//   worker.exchange(frame);  // on every frame, from OBS's thread
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "plugins/obs/frame_planes.h"
#include "plugins/obs/picture_maker.h"
#include "plugins/obs/settings.h"

namespace ifsfx::obs {

using Clock = std::chrono::steady_clock;

// A frame: its planes (OBS's memory, wrapped, or a copy), format, colours and timestamp (ns).
struct FrameData {
  PixelFormat format = PixelFormat::bgra;
  cv::Size size;
  YuvMatrix yuv;
  bool flip = false;  // stored upside down (OBS shows it turned upright)
  std::uint64_t timestamp = 0;
  std::vector<cv::Mat> planes;
};

// What exchange() wrote into a frame.
struct Shown {
  bool written = false;         // false: no picture yet (or of another format or size)
  std::uint64_t timestamp = 0;  // the timestamp of the frame the picture was made of
  Clock::time_point submitted;  // when that frame reached exchange()
  Clock::time_point finished;   // when its picture was ready
};

struct WorkerStats {
  std::int64_t frames = 0;    // exchange() calls
  std::int64_t filtered = 0;  // pictures made
  std::int64_t dropped = 0;   // frames replaced by a newer one before the worker took them
  std::int64_t repeated = 0;  // frames that showed a picture already shown
  std::int64_t passed = 0;    // frames left as they were (no picture yet)
};

class FilterWorker {
 public:
  // `frame_rate`: the rate the animation counts frames by (OBS's video rate), as --fps does for
  // `ifsfx filter`'s image sequences.
  explicit FilterWorker(double frame_rate);
  ~FilterWorker();  // stops a build in progress (its cancel flag) and the thread
  FilterWorker(const FilterWorker&) = delete;
  FilterWorker& operator=(const FilterWorker&) = delete;

  // Settings for the next frames (checked by the caller: check_settings); clears status().
  void configure(const PluginSettings& settings);
  // Settings that could not be used: `message` becomes status(), the last good ones stay.
  void reject(const std::string& message);

  // OBS's video thread: hands the worker a copy of `frame` and writes the newest picture of the
  // same format and size into frame.planes. Waits for nothing but a lock held for pointer swaps.
  Shown exchange(FrameData& frame);

  // "" while the settings work; else the one-line message of the last failure.
  std::string status() const;
  WorkerStats stats() const;

 private:
  struct Picture {
    FrameData frame;  // the picture in the frame's format, the frame's timestamp
    Clock::time_point submitted, finished;
  };
  struct Wanted {
    PluginSettings settings;
    std::int64_t generation = -1;  // -1: nothing configured yet
  };

  void run();
  void make(FrameData& job, Clock::time_point submitted, const Wanted& wanted);
  // A maker for `wanted` and frames of `size`: the one in use, a build that has finished, or
  // none yet (a build is started); nullptr while there is nothing to filter with.
  PictureMaker* maker_for(const Wanted& wanted, cv::Size size);
  void fail(const std::string& message);

  const double frame_rate_;
  std::atomic<bool> stop_{false};  // the builds' cancel flag, and the thread's
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  // Three frame buffers turn round: OBS's thread fills spare_ and swaps it with pending_, the
  // newest frame not yet taken (valid when has_pending_); the worker swaps that with job_.
  FrameData spare_;
  FrameData pending_;
  Clock::time_point pending_at_;
  bool has_pending_ = false;
  Wanted wanted_;
  std::shared_ptr<const Picture> newest_;
  std::uint64_t last_shown_ = 0;
  bool shown_any_ = false;
  WorkerStats stats_;
  std::string status_;

  // The worker thread's own.
  FrameData job_;
  std::unique_ptr<PictureMaker> maker_;
  std::future<std::unique_ptr<PictureMaker>> build_;
  std::int64_t build_generation_ = -1, failed_generation_ = -1;
  cv::Size build_size_;
  std::optional<std::uint64_t> first_timestamp_;
  std::thread thread_;  // last: started when everything else exists
};

}  // namespace ifsfx::obs
