// SPDX-License-Identifier: Apache-2.0
#include "engine/camera_drift.h"

#include <chrono>

#include "ifs/sampling.h"

namespace ifsfx::engine {

LiveDrift::LiveDrift(const Drawing& base, const Ifs& colouring, cv::Size size,
                     const LiveDriftOptions& options)
    : base_(base), colouring_(colouring), size_(size), options_(options) {
  // The view fixed from the base IFS, so that the frame does not jump as the attractor moves.
  options_.map = with_fixed_view(base_, size_, options_.map);
  if (options_.fade_frames < 1) options_.fade_frames = 1;
  current_ = std::make_shared<const PreparedStealMap>(build(0));
  previous_ = current_;
  fade_ = options_.fade_frames;
  built_ = 1;
}

LiveDrift::~LiveDrift() {
  if (pending_.valid()) pending_.wait();
}

PreparedStealMap LiveDrift::build(double t) const {
  const Drawing now = drift(base_, t, options_.drift);
  return prepare_filter(steal_map(now, colouring_, size_, options_.map), size_,
                        options_.interpolation, options_.map.sampling.threads);
}

cv::Mat LiveDrift::filter(const cv::Mat& frame, double t, const FilterOptions& options) {
  if (pending_.valid() && pending_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    previous_ = current_;
    current_ = std::make_shared<const PreparedStealMap>(pending_.get());  // rethrows a failed build
    fade_ = 0;
    ++built_;
  }
  if (!pending_.valid()) pending_ = std::async(std::launch::async, [this, t] { return build(t); });
  if (fade_ >= options_.fade_frames) return filter_frame(frame, *current_, options);
  ++fade_;
  return filter_frame(frame, *previous_, *current_,
                      static_cast<double>(fade_) / options_.fade_frames, options);
}

}  // namespace ifsfx::engine
