// SPDX-License-Identifier: Apache-2.0
// Textures from a superIFS (paper §5, Fig. 4–5): a buffer of the V-variable step rendered as a
// set, as fractal tops, coloured by colour stealing, or as its measure; and texture sequences —
// every further step a new texture of the same family, optionally crossfaded for animation.
//
// Steal coordinates and tops come from an exact descent through the buffers' history
// (docs/design.md §3 and §5): from pixel x of buffer v at step k, pick the highest m whose preimage
// f^{n_v}_m⁻¹(x) lies in buffer v_m one step back, continue there with x ← f⁻¹(x), L times; then
// T(x) = g^{n_1}_{m_1} ∘ … ∘ g^{n_L}_{m_L}(ρ(x_L)), where ρ maps the buffers' plane rectangle onto
// the colouring's unit square (the steal coordinates of the starting buffer, the whole
// rectangle). x is never snapped to the grid, so a superIFS whose IFSs all equal its colouring
// tiling returns the source image exactly.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/steal_map.h"
#include "ifs/timeline.h"
#include "superifs/buffers.h"
#include "superifs/superifs.h"

namespace ifsfx {

enum class TextureMode {
  attractor,  // the set K_v, white on black (CV_8UC1)
  tops,       // the top address of each pixel through a colour ramp (CV_8UC3)
  steal,      // colours stolen from a source image (the source's type)
  measure,    // the measure μ_v, log-density tone-mapped, coloured by map (CV_8UC3)
};

const char* to_string(TextureMode mode) noexcept;
// "attractor", "tops", "steal" or "measure"; throws Error{parse} naming `what` otherwise.
TextureMode parse_texture_mode(const std::string& text, const std::string& what = "mode");

// Descent depth that brings the colouring's pieces below a pixel of a raster of `pixels` on its
// longer side: the least L with s_G^L · pixels < 1, capped at 64.
int descent_depth(const SuperIfs& super, int pixels);

// The steal map of buffer v (from 0): source_uv = T(x) in normalised image coordinates of the
// source (u right, v down), coverage = K_v. Uses every level of buffers.history(); throws
// Error{invalid_argument} when the buffers keep no history after steps were taken.
//   Buffers K(super, {512, 512}, {.history = descent_depth(super, 512)});
//   K.run(12); auto T = steal_map(K, 0);  auto img = apply(T, photo);
StealMap steal_map(const Buffers& buffers, std::size_t v);

// The buffer rendered in `mode` (see TextureMode). `source` is the image colours are stolen from
// in steal mode and is ignored otherwise. Tops and steal need history; measure needs density.
cv::Mat render_buffer(const Buffers& buffers, std::size_t v, TextureMode mode,
                      const cv::Mat& source = {});

// The longest loop of textures (TextureOptions::loop).
inline constexpr std::int64_t kMaxLoop = 1000000;

struct TextureOptions {
  // The plane rectangle (default: the superIFS's view, else its attractor auto-framed with the
  // margin), the seed of every choice (stream_seed(seed, step)), threads, and the stop flag,
  // polled by the burn-in, the steps and the descent (per band of rows). Quality is not used.
  // With sampling.seamless the texture is one period of a doubly periodic one, the buffers on
  // the torus of their rectangle (BufferOptions, docs/design.md §11).
  Sampling sampling;
  int count = 3;   // V, the number of buffers
  int steps = 0;   // burn-in steps; 0 = default_steps(super, size)
  int buffer = 0;  // the buffer shown, from 0
  TextureMode mode = TextureMode::attractor;
  cv::Mat source;  // steal mode: the image frame() steals colours from (its size also sets the
                   // descent depth); may be empty when only maps are wanted
  // A loop of this many textures, 0 = an endless sequence: the choices repeat with this period,
  // the burn-in runs until the buffers come back to themselves after a period, and texture k is
  // texture k mod loop (docs/design.md §12).
  std::int64_t loop = 0;
};

// One texture: V buffers burnt in for options.steps, buffer options.buffer rendered in
// options.mode. Throws Error{invalid_argument} for a bad buffer index, steps or missing source.
//   cv::Mat t = render_texture(load_superifs("paper-fig4").super, {2048, 2048},
//                              {.mode = TextureMode::steal, .source = photo});
cv::Mat render_texture(const SuperIfs& super, cv::Size size, const TextureOptions& options = {});

// An endless, non-repeating sequence of textures of one family: the burnt-in buffers, then one
// V-variable step per texture. With options.loop = N, a loop instead: textures k and k + N are
// one texture, and the step from texture N − 1 to texture N = 0 is one V-variable step like every
// other (docs/design.md §12). The video filter calls next_map() (or map_at(k) for keyframe k)
// every K frames and colours its frames with apply(map, frame). For steal maps, construct it
// with mode steal or tops: the other modes keep no history to descend through.
//   TextureSequence seq(super, {1920, 1080}, {.count = 3});
//   for (;;) { StealMap T = seq.next_map(); ... apply(T, frame) ... }
class TextureSequence {
 public:
  // Validates the options and runs the burn-in (options.steps, or the default); with a loop, then
  // whole periods until the buffers close (at most max(8 · burn-in, 4 · loop) steps more).
  TextureSequence(const SuperIfs& super, cv::Size size, const TextureOptions& options = {});

  // The current texture rendered in options.mode.
  cv::Mat frame() const;
  // The steal map of the shown buffer now (mode steal or tops: the others keep no history).
  StealMap steal_map() const;
  // One further V-variable step: the next texture of the family.
  void step() { buffers_.step(); }
  // step(), then the steal map of the new texture.
  StealMap next_map();

  // The steal map of texture k ≥ 0 of the sequence (k = 0: the burnt-in one), a pure function of
  // k for a given superIFS, size and options, whatever order steps are asked for in: the sequence
  // steps forward to k keeping the maps of the last 4 steps, so keyframes asked for in about
  // increasing order (a lookahead) are cheap; a step already passed and no longer kept is made
  // again from the burn-in (k steps' work). Safe to call from several threads (calls are
  // serialised). Throws Error{invalid_argument} for a negative k.
  StealMap map_at(std::int64_t k);

  // Texture k ≥ 0 rendered in options.mode, a pure function of k like map_at (the last 4 kept;
  // the image shares its pixels with the kept one: copy it before writing to it).
  cv::Mat frame_at(std::int64_t k);
  // The frame of an animation at `position`: texture position.step crossfaded towards the next
  // one by position.phase (crossfade() below).
  //   for (int j = 0; j < frames; ++j) write(seq.frame_at(position_of_frame(j, 4)));
  cv::Mat frame_at(StepPosition position);

  int steps_done() const { return buffers_.steps_done(); }
  std::int64_t loop() const { return options_.loop; }  // textures in the loop, 0 = none
  // Steps before texture 0: the burn-in, and with a loop the periods until the buffers closed.
  int burn_in() const { return burn_in_; }
  // With a loop: whether the buffers came back to themselves, so that stepping on from texture
  // N − 1 gives texture 0 exactly (sets, tops, steal maps; the measure to 1e-6 of its largest
  // value). False when they did not within the limit: the loop still repeats (texture k is texture
  // k mod N), but its last step is not one V-variable step. True without a loop.
  bool loop_closed() const { return loop_closed_; }
  const Buffers& buffers() const { return buffers_; }

 private:
  // Moves the buffers to step k (from the burn-in again when k is behind them).
  void seek(std::int64_t k);
  // With a loop: whole periods after the burn-in until the buffers close (docs/design.md §12).
  void close_loop(int burn_in);
  // k, or k mod the loop.
  std::int64_t in_loop(std::int64_t k) const;

  TextureOptions options_;
  Buffers buffers_;
  int burn_in_ = 0;
  bool loop_closed_ = true;
  std::optional<Buffers> loop_start_;            // with a loop: the buffers of texture 0
  std::mutex mutex_;                             // serialises map_at and frame_at
  std::map<std::int64_t, StealMap> kept_maps_;   // the last maps map_at made, by k
  std::map<std::int64_t, cv::Mat> kept_frames_;  // the last frames frame_at made, by k
};

// Linear crossfade (1 − t)·a + t·b of two images of one size and type, t in [0, 1]: the frames
// between two textures of a sequence.
cv::Mat crossfade(const cv::Mat& a, const cv::Mat& b, double t);

}  // namespace ifsfx
