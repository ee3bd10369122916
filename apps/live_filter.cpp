#include "apps/live_filter.h"

#include "apps/cli_options.h"
#include "ifs/preset.h"

namespace ifsfx::app {

LiveFilter::LiveFilter(const FractalFilterArgs& args, int fade_frames, const std::string& preset,
                       cv::Size size, bool animate)
    : args_(args), fade_frames_(fade_frames), size_(size) {
  const IfsPreset F = load_preset(preset);
  F_ = F.ifs;
  name_ = F.ifs.name.empty() ? preset : F.ifs.name;
  G_ = colouring_option(args.colouring, F_);
  map_options_ = args.map_options();
  options_ = args.filter_options();
  fixed_ = video::make_remap_table(compute_steal_map(F_, G_, size, map_options_), size,
                                   Interpolation::bilinear, args.threads);
  set_animate(animate);
}

void LiveFilter::set_animate(bool on) {
  if (!on) {
    drift_.reset();
    return;
  }
  if (drift_) return;
  video::LiveDriftOptions o;
  o.drift = args_.drift_options();
  o.map = map_options_;
  o.fade_frames = fade_frames_;
  drift_ = std::make_unique<video::LiveDrift>(F_, G_, size_, o);
}

cv::Mat LiveFilter::operator()(const video::Frame& frame) {
  if (!drift_) return video::filter_frame(frame.image, fixed_, options_);
  return drift_->filter(frame.image, frame.timestamp, options_);
}

}  // namespace ifsfx::app
