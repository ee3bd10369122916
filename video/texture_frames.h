// SPDX-License-Identifier: Apache-2.0
// The frames of a texture sequence (`ifsfx texture --frames N`, superifs/texture.h) as a frame
// source, so that they go through the movie pipeline (video/pipeline.h) into any sink: a movie
// (.mp4, .webm, .gif, animated .webp, ...) or an image sequence. Frame j shows step j / K of the
// sequence crossfaded towards the next one, or, in a loop of L frames, its place in the loop
// (position_in_loop): frame j is a pure function of j.
#pragma once

#include <cstdint>
#include <string>

#include "superifs/texture.h"
#include "video/frame_io.h"

namespace ifsfx::video {

struct TextureFramesOptions {
  std::int64_t frames = 1;       // frames the source gives
  int crossfade = 1;             // frames per step of the sequence (K)
  std::int64_t loop = 0;         // frames in a loop (L), 0 = none; the sequence's loop must then be
                                 // steps_in_loop(L, K) textures
  Rational rate{25, 1};          // frames per second
  std::string name = "texture";  // for messages
};

// Reads frames 0..frames − 1 of `textures` (which must outlive the source) as 8-bit BGR, frame j
// at j / rate seconds. Throws Error{invalid_argument} for a bad count, crossfade or rate, and a
// loop whose textures do not match the sequence's.
//   TextureFrames source(seq, {.frames = 48, .crossfade = 4, .loop = 48});
//   run_pipeline(source, movie, [](const Frame& f) { return f.image; });
class TextureFrames final : public FrameSource {
 public:
  TextureFrames(TextureSequence& textures, const TextureFramesOptions& options);
  std::optional<Frame> read() override;
  bool skip() override;
  bool seek(std::int64_t index) override;
  cv::Size size() const override { return size_; }
  double fps() const override { return options_.rate.value(); }
  Rational frame_rate() const override { return options_.rate; }
  Rational time_base() const override { return {options_.rate.den, options_.rate.num}; }
  std::int64_t frame_count() const override { return options_.frames; }
  std::string name() const override { return options_.name; }

  // Where frame j of the source stands in the sequence.
  StepPosition position(std::int64_t j) const;

 private:
  TextureSequence& textures_;
  TextureFramesOptions options_;
  cv::Size size_;
  std::int64_t next_ = 0;
};

}  // namespace ifsfx::video
