// SPDX-License-Identifier: Apache-2.0
#include "run/texture_options.h"

#include <map>

#include <fmt/format.h>

#include "ifs/error.h"
#include "run/arguments.h"
#include "run/texture_movie.h"

namespace ifsfx::app {

void check_texture_rules(const TextureArgs& args, const TextureArgNames& names) {
  if (args.count < 1 || args.count > kMaxTextureBuffers)
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: must be 1..{} (got {})", names.count,
                                                         kMaxTextureBuffers, args.count));
  if (args.frames < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: must be ≥ 1 (got {})", names.frames, args.frames));
  if (args.crossfade < 1)
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: must be ≥ 1 frame per step (got {})",
                                                         names.crossfade, args.crossfade));
  if (args.buffer < 1 || args.buffer > args.count)  // the library counts buffers from 0
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: must be 1..{} for V = {} (got {})", names.buffer, args.count,
                            args.count, args.buffer));
  if (args.mode == TextureMode::steal && args.source.empty())
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: steal mode needs a source image to steal colours from", names.source));
  if ((args.fps_given || !args.codec.empty()) && !writes_texture_movie(args))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: only a movie output (.mp4, .webm, .gif, .webp, ...) is encoded "
                            "(got {})",
                            args.fps_given ? names.fps : names.codec, args.output));
}

cv::Size check_texture_args(const TextureArgs& args) {
  const cv::Size size = size_option(args.size);
  check_texture_rules(args);
  return size;
}

}  // namespace ifsfx::app
