// SPDX-License-Identifier: Apache-2.0
#include "video/texture_frames.h"

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::video {

TextureFrames::TextureFrames(TextureSequence& textures, const TextureFramesOptions& options)
    : textures_(textures), options_(options), size_(textures.buffers().size()) {
  if (options.frames < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("frames: must be ≥ 1 (got {})", options.frames));
  if (options.crossfade < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("crossfade: must be ≥ 1 frame per step (got {})", options.crossfade));
  if (!options.rate.positive())
    throw Error(ErrorKind::invalid_argument, fmt::format("frame rate: must be positive (got {}/{})",
                                                         options.rate.num, options.rate.den));
  const std::int64_t steps =
      options.loop > 0 ? steps_in_loop(options.loop, options.crossfade) : std::int64_t{0};
  if (options.loop < 0 || textures.loop() != steps)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("loop: {} frames at {} a step need a loop of {} textures (got {})",
                            options.loop, options.crossfade, steps, textures.loop()));
}

StepPosition TextureFrames::position(std::int64_t j) const {
  return options_.loop > 0 ? position_in_loop(j, options_.crossfade, options_.loop)
                           : position_of_frame(j, options_.crossfade);
}

std::optional<Frame> TextureFrames::read() {
  if (next_ >= options_.frames) return std::nullopt;
  Frame frame;
  frame.index = next_;
  frame.pts = next_;
  frame.duration = 1;
  frame.time_base = time_base();
  frame.timestamp = static_cast<double>(next_) * options_.rate.den / options_.rate.num;
  const cv::Mat texture = textures_.frame_at(position(next_));
  frame.image = to_bgr8(texture);
  // The sequence keeps its last frames: the sink gets pixels of its own.
  if (frame.image.data == texture.data) frame.image = frame.image.clone();
  ++next_;
  return frame;
}

bool TextureFrames::skip() {
  if (next_ >= options_.frames) return false;
  ++next_;
  return true;
}

bool TextureFrames::seek(std::int64_t index) {
  if (index < 0 || index > options_.frames) return false;
  next_ = index;
  return index < options_.frames;
}

}  // namespace ifsfx::video
