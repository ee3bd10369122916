// SPDX-License-Identifier: Apache-2.0
// The filter of `ifsfx cam`: F coloured through G on the camera's frame size (docs/design.md §3) —
// one steal map computed once and reapplied per frame, or, animated, maps of F drifting in time
// built on a worker and cross-faded in (engine/camera_drift.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "engine/camera_drift.h"
#include "engine/fractal_engine.h"
#include "run/fractal_filter_options.h"
#include "video/frame_io.h"

namespace ifsfx::app {

class LiveFilter {
 public:
  // Computes the steal map of `preset` (a shipped name, a path, FILE.ifs:NAME) for frames of
  // `size`, with the colouring, view and map options of `args`; `fps` is the camera's rate (a
  // --loop of N frames lasts N / fps seconds).
  LiveFilter(const FractalFilterArgs& args, int fade_frames, const std::string& preset,
             cv::Size size, bool animate, double fps = 25);

  const std::string& name() const { return engine_->name(); }
  bool animated() const { return drift_ != nullptr; }
  // Starts or stops the drift animation (stopping waits for a map being built).
  void set_animate(bool on);
  // Maps the animation has built since it was last started.
  std::int64_t maps_built() const { return drift_ ? drift_->maps_built() : 0; }

  cv::Mat operator()(const video::Frame& frame);

 private:
  int fade_frames_;
  cv::Size size_;
  std::unique_ptr<engine::FractalEngine> engine_;  // the fixed map, and F, G for the drift
  std::unique_ptr<engine::LiveDrift> drift_;
};

}  // namespace ifsfx::app
