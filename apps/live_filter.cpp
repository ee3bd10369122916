// SPDX-License-Identifier: Apache-2.0
#include "apps/live_filter.h"

#include "apps/cli_options.h"

namespace ifsfx::app {

LiveFilter::LiveFilter(const FractalFilterArgs& args, int fade_frames, const std::string& preset,
                       cv::Size size, bool animate, double fps)
    : fade_frames_(fade_frames), size_(size) {
  video::FractalSettings settings = args.settings();
  settings.preset = preset;
  engine_ = std::make_unique<video::FractalEngine>(settings, size, size, fps);
  print_warnings(engine_->warnings());
  set_animate(animate);
}

void LiveFilter::set_animate(bool on) {
  if (!on) {
    drift_.reset();
    return;
  }
  if (drift_) return;
  // A camera's frames do not wait for maps: the live drift (video/camera_drift.h) rather than the
  // engine's keyframe schedule, on the engine's F, G and map options.
  video::LiveDriftOptions o;
  o.drift = engine_->drift_options();
  o.map = engine_->map_options();
  o.fade_frames = fade_frames_;
  drift_ = std::make_unique<video::LiveDrift>(engine_->drawing(), engine_->colouring(), size_, o);
}

cv::Mat LiveFilter::operator()(const video::Frame& frame) {
  if (!drift_) return engine_->filter(frame.image, frame.index);
  return drift_->filter(frame.image, frame.timestamp, engine_->filter_options());
}

}  // namespace ifsfx::app
