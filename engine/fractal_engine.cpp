// SPDX-License-Identifier: Apache-2.0
#include "engine/fractal_engine.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "engine/drift.h"
#include "engine/map_schedule.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace ifsfx::engine {

Ifs default_drawing() {
  // Parsed once: every FractalSettings starts from it (a plugin makes one per frame). Immutable.
  static const Ifs fern = load_ifs(kDefaultPreset).ifs;
  return fern;
}

bool same_maps(const FractalSettings& a, const FractalSettings& b) {
  FractalSettings looks_like_b = a;
  looks_like_b.mix = b.mix;
  looks_like_b.background = b.background;
  return looks_like_b == b;
}

FractalEngine::FractalEngine(const FractalSettings& settings) : settings_(settings) {
  if (settings.keyframe_interval < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("keyframe interval: must be 1 or more frames (got {})",
                            settings.keyframe_interval));
  if (settings.loop < 0 || settings.loop > kMaxLoop)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("loop: must be 0..{} frames, 0 for none (got {})", kMaxLoop, settings.loop));
  options_.interpolation = settings.interpolation;
  options_.mix = settings.mix;
  options_.background = settings.background;
  options_.threads = settings.sampling.threads;
  check_filter_options(options_);
  if (settings.animate == Animate::superifs) {
    super_ = load_superifs(settings.superifs).super;
    name_ = super_.name.empty() ? settings.superifs : super_.name;
    return;
  }
  F_ = settings.drawing;
  check_drawing(F_);
  name_ = name_of(F_);
  const std::size_t n = map_count(F_);
  G_ = settings.colouring ? *settings.colouring : default_colouring(n);
  if (G_.size() != n)
    throw Error(
        ErrorKind::invalid_ifs,
        fmt::format("colouring: must have {} {} (got {} for {})",
                    std::holds_alternative<Ifs>(F_) ? "as many maps as" : "one map per xform of",
                    name_, G_.size(), n));
  validate(G_, "colouring", {.allow_expansive = true});
  if (std::holds_alternative<flame::Flame>(F_) && settings.sampling.seamless)
    throw Error(ErrorKind::invalid_argument,
                "seamless: a flame is drawn in its own plane, not on the torus of a tile (got a "
                "flame)");
  if (settings.animate == Animate::drift) drift(F_, 0, drift_options());  // checks them
}

FractalEngine::FractalEngine(const FractalSettings& settings, cv::Size frame_size,
                             cv::Size output_size, double frame_rate)
    : FractalEngine(settings) {
  prepare(frame_size, output_size, frame_rate);
}

FractalEngine::~FractalEngine() = default;

DriftOptions FractalEngine::drift_options() const {
  return {.amount = settings_.drift_amount,
          .speed = settings_.drift_speed,
          .seed = settings_.sampling.seed,
          .loop = static_cast<double>(settings_.loop) / frame_rate_};
}

std::int64_t FractalEngine::loop_keyframes() const {
  return settings_.loop > 0 ? steps_in_loop(settings_.loop, settings_.keyframe_interval) : 0;
}

StealMapOptions FractalEngine::map_options() const {
  return {.sampling = settings_.sampling, .exact = settings_.exact};
}

void FractalEngine::prepare(cv::Size frame_size, cv::Size output_size, double frame_rate) {
  if (table_ || schedule_)
    throw Error(ErrorKind::invalid_argument, "fractal engine: already prepared");
  if (!(frame_rate > 0) || !std::isfinite(frame_rate))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("frame rate: must be a positive number (got {})", frame_rate));
  frame_rate_ = frame_rate;
  const cv::Size size = output_size.empty() ? frame_size : output_size;
  const FractalSettings& s = settings_;
  StealMapOptions map_options = this->map_options();
  // A live source's keyframes are built on one thread beside the frames (map_schedule.h); the
  // maps do not depend on the threads.
  const int threads = s.sampling.threads;
  const int build_threads = s.live ? 1 : threads;
  const ScheduleOptions schedule{.live = s.live};
  const Interpolation interpolation = s.interpolation;
  switch (s.animate) {
    case Animate::none:
      table_ = std::make_shared<const PreparedStealMap>(
          prepare_filter(steal_map(F_, G_, size, map_options), frame_size, interpolation, threads));
      return;
    case Animate::drift: {
      // Keyframe k shows F drifted to time k·K/fps, in a view fixed from F itself so that the
      // frame does not jump as the attractor moves (a flame's camera holds still already).
      map_options = with_fixed_view(F_, size, map_options);
      map_options.sampling.threads = build_threads;
      // With a loop of L frames and Q keyframes, keyframe k shows time (k mod Q) · L / Q frames:
      // keyframe Q is keyframe 0, and the drift's own period is the loop.
      schedule_ = std::make_unique<MapSchedule>(
          [=, F = F_, G = G_, drift_options = drift_options(), interval = s.keyframe_interval,
           fps = frame_rate, loop = s.loop, q = loop_keyframes()](std::int64_t k) {
            const double frames = loop > 0 ? static_cast<double>(k % q) *
                                                 static_cast<double>(loop) / static_cast<double>(q)
                                           : static_cast<double>(k) * interval;
            const Drawing now = drift(F, frames / fps, drift_options);
            return prepare_filter(steal_map(now, G, size, map_options), frame_size, interpolation,
                                  build_threads);
          },
          s.keyframe_interval, schedule);
      return;
    }
    case Animate::superifs: {
      // Keyframe k is texture k of the V-variable sequence (paper §5, eq. 14), one step per
      // keyframe after the burn-in — a pure function of k and the seed.
      TextureOptions t;
      t.sampling = s.sampling;
      t.sampling.view.reset();  // the superIFS brings its own
      t.sampling.threads = build_threads;
      t.count = s.buffers;
      t.mode = TextureMode::steal;
      t.source = cv::Mat(frame_size, CV_8UC3);  // only its size: it sets the descent depth
      t.loop = loop_keyframes();                // texture k of a loop of Q is texture k mod Q
      sequence_ = std::make_shared<TextureSequence>(super_, size, t);
      schedule_ = std::make_unique<MapSchedule>(
          [=, sequence = sequence_](std::int64_t k) {
            return prepare_filter(sequence->map_at(std::max<std::int64_t>(k, 0)), frame_size,
                                  interpolation, build_threads);
          },
          s.keyframe_interval, schedule);
      return;
    }
  }
}

void FractalEngine::set_look(double mix, const Background& background) {
  FilterOptions options = options_;
  options.mix = mix;
  options.background = background;
  check_filter_options(options);
  options_ = options;
  settings_.mix = mix;
  settings_.background = background;
}

cv::Mat FractalEngine::filter(const cv::Mat& frame, std::int64_t index) {
  cv::Mat out;
  filter(frame, index, out);
  return out;
}

void FractalEngine::filter(const cv::Mat& frame, std::int64_t index, cv::Mat& out) {
  if (settings_.loop > 0 && settings_.animate != Animate::none)
    return filter_at(frame, position_in_loop(index, settings_.keyframe_interval, settings_.loop),
                     out);
  filter_at(frame, position_of_frame(index, settings_.keyframe_interval), out);
}

void FractalEngine::filter_at(const cv::Mat& frame, double seconds, cv::Mat& out) {
  // A time on the frame grid is that frame, exactly: the picture `ifsfx filter` gives for it.
  const double frames = seconds * frame_rate_;
  const double nearest = std::round(frames);
  if (std::abs(frames - nearest) <= 1e-6 * std::max(1.0, std::abs(frames)))
    return filter(frame, static_cast<std::int64_t>(nearest), out);
  if (settings_.loop > 0 && settings_.animate != Animate::none) {
    // Between two frames of a loop: its place in the loop, in keyframes.
    const auto length = static_cast<double>(settings_.loop);
    const double in_loop = frames - std::floor(frames / length) * length;
    return filter_at(
        frame, position_of_steps(in_loop * static_cast<double>(loop_keyframes()) / length), out);
  }
  filter_at(frame, position_of_steps(frames / settings_.keyframe_interval), out);
}

void FractalEngine::filter_at(const cv::Mat& frame, StepPosition position, cv::Mat& out) {
  if (table_) return filter_frame(frame, *table_, options_, out);
  if (!schedule_)
    throw Error(ErrorKind::invalid_argument, "fractal engine: prepare() before filtering");
  const MapSchedule::Blend b = schedule_->at(position);
  filter_frame(frame, *b.from, *b.to, b.t, options_, out);
}

std::int64_t FractalEngine::stalls() const {
  return schedule_ ? schedule_->stalls() : 0;
}

}  // namespace ifsfx::engine
