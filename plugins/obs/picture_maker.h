// SPDX-License-Identifier: Apache-2.0
// One filtered picture per frame for the OBS filter's mode: `steal` is engine::FractalEngine, the
// engine of `ifsfx filter` (so the pictures are that command's, bit for bit); `tops` is the tops
// picture of F (ifs/steal_picture.h), made once, laid over the frame as the engine lays a steal
// picture: `background` where the attractor is not, then `mix` of the frame over it.
//
//   PictureMaker maker(settings, {1280, 720}, 30);   // slow: builds the maps
//   maker.make(bgr, seconds_since_first_frame, out);
#pragma once

#include <memory>

#include <opencv2/core.hpp>

#include "engine/fractal_engine.h"
#include "plugins/obs/settings.h"

namespace ifsfx::obs {

class PictureMaker {
 public:
  // Builds the maps (or starts the animation's keyframes) for `size` frames at `frame_rate`;
  // throws ifsfx::Error as the engine does.
  PictureMaker(const PluginSettings& settings, cv::Size size, double frame_rate);

  // The picture of `frame` (CV_8UC3 BGR, or CV_8UC4 whose fourth channel passes through) at
  // `seconds` on the animation's clock, into `out`.
  void make(const cv::Mat& frame, double seconds, cv::Mat& out);

  // Whether this maker serves `settings` after set_look (the same maps, mode and size).
  bool serves(const PluginSettings& settings, cv::Size size, double frame_rate) const;
  // New mix and background from the next picture on.
  void set_look(const PluginSettings& settings);

  const PluginSettings& settings() const { return settings_; }

 private:
  void lay_tops(const cv::Mat& frame, cv::Mat& out) const;

  PluginSettings settings_;
  cv::Size size_;
  double frame_rate_;
  std::unique_ptr<engine::FractalEngine> engine_;
  cv::Mat tops_;  // tops: BGRA, alpha 255 on the attractor
};

}  // namespace ifsfx::obs
