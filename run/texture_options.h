// SPDX-License-Identifier: Apache-2.0
// The options of `ifsfx texture`, shared by the texture command and `ifsfx farm texture` (which
// hands them on, unchanged, to every shard, and so checks them before it submits anything).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "run/seamless_options.h"
#include "superifs/texture.h"

namespace ifsfx::app {

struct TextureArgs {
  std::string preset;
  std::string output;
  std::string size = "1024x1024";
  int count = 3;
  int steps = 0;
  int buffer = 1;
  TextureMode mode = TextureMode::attractor;
  std::string source;
  std::uint64_t seed = 1;
  int threads = 0;
  int frames = 1;
  std::string frame_range;  // farm shards: write only frames START:END of the sequence
  int crossfade = 1;
  int bits = 8;
  bool quiet = false;
  SeamlessArgs tiles;  // --seamless, --tiles, --tile-offset (run/seamless_options.h)
  // Loops and movies (docs/loops.md): frames in a loop (0 = none); a movie's rate and encoder.
  std::int64_t loop = 0;
  double fps = 25;
  bool fps_given = false;
  std::string codec;
};

// V, the number of buffers a texture may have (the command's -V, Python's buffers=).
inline constexpr int kMaxTextureBuffers = 1000;

// How a door names the options the checks below report on: the command's flags by default;
// Python passes its keywords' names ({.count = "buffers", .buffer = "buffer", ...}).
struct TextureArgNames {
  std::string count = "--buffers", frames = "--frames", crossfade = "--crossfade",
              buffer = "--buffer", source = "--source", fps = "--fps", codec = "--codec";
};

// The rules between options that their parsing does not check (V, the counts, the buffer against
// V, steal mode's source, a movie's fps and codec), each failing with Error{invalid_argument}
// naming the option as `names` says ("--buffer: must be 1..3 for V = 3 (got 4)").
void check_texture_rules(const TextureArgs& args, const TextureArgNames& names = {});

// The size (args.size, "--size: ..."), then check_texture_rules with the command's names; returns
// the size.
cv::Size check_texture_args(const TextureArgs& args);

}  // namespace ifsfx::app
