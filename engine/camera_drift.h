// SPDX-License-Identifier: Apache-2.0
// `--animate drift` for a live camera: the maps of a drifting IFS or flame (engine/drawing.h) built
// on a worker thread that the live loop never waits for. A file filter may wait for each keyframe
// (its frames are not going anywhere); a camera's frames are, so here the animation advances as
// fast as maps can be built, and each new map is cross-faded in over a few frames. The frame rate
// stays the camera's; only the pace of the drift depends on the machine.
#pragma once

#include <cstdint>
#include <future>
#include <memory>

#include "engine/drawing.h"
#include "engine/drift.h"
#include "engine/fractal_filter.h"
#include "ifs/ifs.h"
#include "ifs/steal_map.h"

namespace ifsfx::engine {

struct LiveDriftOptions {
  DriftOptions drift;
  // Steal maps of the drifted IFS. Leave `view` empty to fix it from the base IFS (auto-framed),
  // so that the picture does not jump as the attractor moves.
  StealMapOptions map;
  int fade_frames = 12;  // frames over which a new map replaces the one before
  Interpolation interpolation = Interpolation::bilinear;
};

class LiveDrift {
 public:
  // Builds the map of time 0 before returning (so the first frame does not wait), then the next
  // one in the background. Throws what drift() and compute_steal_map() throw.
  //   LiveDrift live(F, G, {1280, 720}, {.drift = {.amount = 0.05}});
  //   cv::Mat out = live.filter(frame.image, frame.timestamp);
  LiveDrift(const Drawing& base, const Ifs& colouring, cv::Size size,
            const LiveDriftOptions& options = {});
  ~LiveDrift();  // waits for the map being built
  LiveDrift(const LiveDrift&) = delete;
  LiveDrift& operator=(const LiveDrift&) = delete;

  // The frame (CV_8UC3 of `size`) through the newest finished map, cross-faded from the one
  // before while a fade is under way. Starts the map of time `t` (seconds) when the worker is
  // idle. Rethrows a failed build.
  cv::Mat filter(const cv::Mat& frame, double t, const FilterOptions& options = {});

  std::int64_t maps_built() const { return built_; }

 private:
  PreparedStealMap build(double t) const;

  Drawing base_;
  Ifs colouring_;
  cv::Size size_;
  LiveDriftOptions options_;
  std::shared_ptr<const PreparedStealMap> previous_, current_;
  std::future<PreparedStealMap> pending_;
  int fade_ = 0;
  std::int64_t built_ = 0;
};

}  // namespace ifsfx::engine
