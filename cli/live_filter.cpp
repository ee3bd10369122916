// SPDX-License-Identifier: Apache-2.0
#include "cli/live_filter.h"

#include "cli/stop_signals.h"

#include "cli/cli_options.h"

namespace ifsfx::app {

LiveFilter::LiveFilter(const FractalFilterArgs& args, int fade_frames, const std::string& preset,
                       cv::Size size, bool animate, double fps)
    : fade_frames_(fade_frames), size_(size) {
  FractalFilterArgs fractal = args;
  fractal.preset = preset;
  std::vector<std::string> warnings;
  engine::FractalSettings settings = fractal.settings(&warnings);
  print_warnings(warnings);
  settings.sampling.cancel = StopSignals::token();  // Ctrl-C stops a map being computed
  engine_ = std::make_unique<engine::FractalEngine>(settings, size, size, fps);
  set_animate(animate);
}

void LiveFilter::set_animate(bool on) {
  if (!on) {
    drift_.reset();
    return;
  }
  if (drift_) return;
  // A camera's frames do not wait for maps: the live drift (engine/camera_drift.h) rather than the
  // engine's keyframe schedule, on the engine's F, G and map options.
  engine::LiveDriftOptions o;
  o.drift = engine_->drift_options();
  o.map = engine_->map_options();
  o.fade_frames = fade_frames_;
  drift_ = std::make_unique<engine::LiveDrift>(engine_->drawing(), engine_->colouring(), size_, o);
}

cv::Mat LiveFilter::operator()(const video::Frame& frame) {
  if (!drift_) return engine_->filter(frame.image, frame.index);
  return drift_->filter(frame.image, frame.timestamp, engine_->filter_options());
}

}  // namespace ifsfx::app
