// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/picture_maker.h"

#include <opencv2/imgproc.hpp>

#include "ifs/steal_picture.h"
#include "ifs/tops.h"

namespace ifsfx::obs {

PictureMaker::PictureMaker(const PluginSettings& settings, cv::Size size, double frame_rate)
    : settings_(settings),
      size_(size),
      frame_rate_(frame_rate),
      engine_(std::make_unique<engine::FractalEngine>(settings.engine)) {
  if (settings.mode == Mode::steal) {
    engine_->prepare(size, size, frame_rate);
    return;
  }
  const TopsOptions options{.sampling = engine_->map_options().sampling,
                            .exact = settings.engine.exact};
  // BGRA in [0, 1], alpha the coverage: as bytes.
  engine::tops_picture(engine_->drawing(), size, options, Rgb{}, true).convertTo(tops_, CV_8U, 255);
}

void PictureMaker::make(const cv::Mat& frame, double seconds, cv::Mat& out) {
  if (settings_.mode == Mode::steal) return engine_->filter_at(frame, seconds, out);
  lay_tops(frame, out);
}

bool PictureMaker::serves(const PluginSettings& s, cv::Size size, double frame_rate) const {
  return s.mode == settings_.mode && size == size_ && frame_rate == frame_rate_ &&
         engine::same_maps(s.engine, settings_.engine);
}

void PictureMaker::set_look(const PluginSettings& s) {
  settings_.engine.mix = s.engine.mix;
  settings_.engine.background = s.engine.background;
  engine_->set_look(s.engine.mix, s.engine.background);
}

void PictureMaker::lay_tops(const cv::Mat& frame, cv::Mat& out) const {
  cv::Mat bgr = frame;
  if (frame.channels() == 4) cv::cvtColor(frame, bgr, cv::COLOR_BGRA2BGR);
  const engine::Background& b = settings_.engine.background;
  cv::Mat base = b.kind == engine::BackgroundKind::original
                     ? bgr.clone()
                     : cv::Mat(size_, CV_8UC3, cv::Scalar(b.colour[0], b.colour[1], b.colour[2]));
  cv::Mat tops_bgr, alpha;
  cv::cvtColor(tops_, tops_bgr, cv::COLOR_BGRA2BGR);
  cv::extractChannel(tops_, alpha, 3);
  tops_bgr.copyTo(base, alpha);
  const double mix = settings_.engine.mix;
  if (mix > 0) cv::addWeighted(bgr, mix, base, 1 - mix, 0, base);
  if (frame.channels() == 3) return base.copyTo(out);
  // The frame's fourth channel passes through, as the engine's does.
  cv::Mat channels[4];
  cv::split(frame, channels);
  cv::Mat picture[3];
  cv::split(base, picture);
  const cv::Mat merged[4] = {picture[0], picture[1], picture[2], channels[3]};
  cv::merge(merged, 4, out);
}

}  // namespace ifsfx::obs
