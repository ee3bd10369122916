// SPDX-License-Identifier: Apache-2.0
// Progress of a long video job, reported by the library through a callback: the library never
// prints (the command line draws the bar, a GUI could draw its own).
#pragma once

#include <cstdint>
#include <functional>

namespace ifsfx::video {

struct Progress {
  std::int64_t done = 0;    // frames written so far
  std::int64_t total = -1;  // frames expected in all; -1 when unknown (a camera, a bare stream)
  double seconds = 0;       // wall time since the work started
  bool finished = false;    // the last report of the job

  double fps() const { return seconds > 0 ? static_cast<double>(done) / seconds : 0; }
  // Seconds still to go at the mean rate so far; negative when unknown.
  double eta() const {
    if (total < 0 || done <= 0) return -1;
    return static_cast<double>(total - done) / fps();
  }
};

using ProgressCallback = std::function<void(const Progress&)>;

}  // namespace ifsfx::video
