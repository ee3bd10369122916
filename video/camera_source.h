// SPDX-License-Identifier: Apache-2.0
// A live frame source: a camera, or a paced synthetic pattern standing in for one. Frames are
// produced in real time whether or not anyone reads them; read() returns the newest one and drops
// the older ones (low latency beats completeness for a live view), counting what it dropped.
#pragma once

#include <chrono>
#include <cstdint>

#include "video/frame_io.h"

namespace ifsfx::video {

class LiveSource : public FrameSource {
 public:
  // Frame::timestamp of a live source is its capture time in seconds after clock_origin(), on
  // the steady clock (CLOCK_MONOTONIC, the clock of V4L2 buffer timestamps): latency is
  // now − (clock_origin() + timestamp).
  virtual std::chrono::steady_clock::time_point clock_origin() const = 0;
  // Frames captured but never returned by read(), so far.
  virtual std::int64_t dropped() const = 0;
};

}  // namespace ifsfx::video
