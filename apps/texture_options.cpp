// SPDX-License-Identifier: Apache-2.0
#include "apps/texture_options.h"

#include <map>

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/texture_movie.h"
#include "ifs/error.h"

namespace ifsfx::app {

void add_texture_options(CLI::App& cmd, const std::shared_ptr<TextureArgs>& args) {
  cmd.add_option("--size", args->size, "Output size WxH in pixels")->capture_default_str();
  cmd.add_option("-V,--buffers", args->count, "V, the number of buffers (V-variability)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd.add_option("--steps", args->steps,
                 "Burn-in steps; 0 = enough that s^steps x size < 1/8 pixel for the largest "
                 "contraction factor s")
      ->capture_default_str()
      ->check(not_negative());
  cmd.add_option("--buffer", args->buffer, "The buffer shown, 1..V")->capture_default_str();
  const std::map<std::string, TextureMode> modes{{"attractor", TextureMode::attractor},
                                                 {"tops", TextureMode::tops},
                                                 {"steal", TextureMode::steal},
                                                 {"measure", TextureMode::measure}};
  cmd.add_option("--mode", args->mode,
                 "attractor: the set; tops: top addresses through a colour ramp; steal: colours "
                 "stolen from --source; measure: log-density of the measure")
      ->transform(choice(modes))
      ->default_str("attractor")
      ->option_text(choices_text(modes, "attractor"));
  cmd.add_option("--source", args->source, "Image colours are stolen from (steal mode)");
  cmd.add_option("--seed", args->seed, "Random seed: the same seed gives the same texture")
      ->capture_default_str()
      ->check(not_negative());
  add_threads_option(cmd, args->threads);
  cmd.add_option("--crossfade", args->crossfade,
                 "Frames per step of the sequence, blended between consecutive textures")
      ->capture_default_str();
  cmd.add_option("--bits", args->bits, "Bits per channel of PNG/TIFF output: 8 or 16")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16}));
  cmd.add_flag("-q,--quiet", args->quiet, "Do not print the summary line");
  add_seamless_options(cmd, args->tiles);
  // Loops in time and movie output (docs/loops.md).
  cmd.add_option("--loop", args->loop,
                 "A loop of N frames (--frames defaults to N): frame N is frame 0 again, bit for "
                 "bit, the superIFS choices periodic and the buffers closed, so the last frame "
                 "flows into the first; ceil(N / --crossfade) textures spread evenly (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t{0}, kMaxLoop));
  cmd.add_option("--fps", args->fps, "Frame rate of a movie output")
      ->capture_default_str()
      ->check(number_in(0, 1000, true))
      ->each([args](const std::string&) { args->fps_given = true; });
  cmd.add_option("--codec", args->codec,
                 "Video encoder of a movie output (default by container: .mp4/.mkv H.264, .webm "
                 "VP9, .gif GIF, .webp animated WebP; ffv1 in .mkv is lossless)");
}

cv::Size check_texture_args(const TextureArgs& args) {
  const cv::Size size = size_option(args.size);
  if (args.frames < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--frames: must be ≥ 1 (got {})", args.frames));
  if (args.crossfade < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--crossfade: must be ≥ 1 frame per step (got {})", args.crossfade));
  if (args.buffer < 1 || args.buffer > args.count)  // the library counts buffers from 0
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--buffer: must be 1..{} for V = {} (got {})", args.count, args.count,
                            args.buffer));
  if (args.mode == TextureMode::steal && args.source.empty())
    throw Error(ErrorKind::invalid_argument,
                "--source: steal mode needs a source image to steal colours from");
  if ((args.fps_given || !args.codec.empty()) && !writes_texture_movie(args))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: only a movie output (.mp4, .webm, .gif, .webp, ...) is encoded "
                            "(got {})",
                            args.fps_given ? "--fps" : "--codec", args.output));
  return size;
}

}  // namespace ifsfx::app
