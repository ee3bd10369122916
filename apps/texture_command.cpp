// SPDX-License-Identifier: Apache-2.0
// `ifsfx texture SUPERPRESET -o OUT`: a V-variable superfractal texture (paper §5, Fig. 4–5), or
// with --frames a sequence of them, one per further step, optionally crossfaded.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/stop_signals.h"
#include "apps/texture_movie.h"
#include "apps/texture_options.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"

namespace ifsfx::app {
namespace {

void run_texture(const TextureArgs& args) {
  cv::Size size = check_texture_args(args);
  // A numbered pattern (tex_%04d.png) numbers the frames from 1, also a single one; a movie
  // (.mp4, .webm, .gif, .webp, ...) holds them all (apps/texture_movie.h).
  video::check_output_name(args.output);
  const bool numbered = video::is_sequence_pattern(args.output);
  const bool movie = writes_texture_movie(args);
  if (args.frames > 1 && !numbered && !movie)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("-o: --frames needs a numbered pattern like tex_%04d.png or a movie "
                            "(.mp4, .webm, .gif, .webp, ...) (got {})",
                            args.output));
  // A loop of L frames shows ⌈L / K⌉ textures, each K frames or a little less (ifs/timeline.h).
  const auto position_of = [&](std::int64_t frame) {
    return args.loop > 0 ? position_in_loop(frame, args.crossfade, args.loop)
                         : position_of_frame(frame, args.crossfade);
  };
  const auto path_of = [&](int frame) -> std::filesystem::path {
    return numbered ? video::sequence_path(args.output, frame + 1)
                    : std::filesystem::path(args.output);
  };
  // A farm shard writes its own frames; each is a pure function of its index (map_at).
  int first = 0, last = args.frames - 1;
  if (!args.frame_range.empty()) {
    const video::FrameRange range = video::parse_frame_range(args.frame_range, "--frame-range");
    first = static_cast<int>(std::min<std::int64_t>(range.first, args.frames));
    if (range.last >= 0) last = static_cast<int>(std::min<std::int64_t>(range.last, last));
  }
  // The output policy: no frame replaces an input; every name is checked before the burn-in.
  StopSignals signals;
  OutputOptions output{.cancel = StopSignals::token()};
  add_preset_input(output.inputs, args.preset);
  output.inputs.add(args.source);
  if (movie) {
    size = check_texture_movie(args, size, output);
  } else {
    if (first <= last) check_writable_image(path_of(first), output, args.bits);
    for (int frame = first + 1; frame <= last; ++frame) check_output(path_of(frame), output);
  }
  const SuperIfsPreset preset = load_superifs(args.preset);

  TextureOptions options{
      .sampling = {.seed = args.seed, .threads = args.threads, .cancel = output.cancel},
      .count = args.count,
      .steps = args.steps,
      .buffer = args.buffer - 1,
      .mode = args.mode};
  options.loop = args.loop > 0 ? steps_in_loop(args.loop, args.crossfade) : 0;
  if (!args.source.empty()) options.source = read_image(args.source).pixels;

  const auto start = std::chrono::steady_clock::now();
  TextureSequence textures(preset.super, size, options);
  const std::string name = preset.super.name.empty() ? args.preset : preset.super.name;
  const auto metadata = [&](int step) {
    WriteOptions write;
    write.bits = args.bits;
    write.metadata = {
        {"ifsfx:superpreset", preset.text},
        {"ifsfx:superpreset_name", name},
        {"ifsfx:mode", to_string(args.mode)},
        {"ifsfx:V", std::to_string(args.count)},
        {"ifsfx:buffer", std::to_string(args.buffer)},
        {"ifsfx:seed", std::to_string(args.seed)},
        {"ifsfx:steps", std::to_string(step)},
        {"ImageDescription", fmt::format("ifsfx texture {} -V {} --mode {} --seed {} --steps {}",
                                         name, args.count, to_string(args.mode), args.seed, step)},
    };
    if (args.loop > 0) {  // the loop's burn-in is its own: --steps does not say which texture
      write.metadata.back().second =
          fmt::format("ifsfx texture {} -V {} --mode {} --seed {} --loop {} --crossfade {}", name,
                      args.count, to_string(args.mode), args.seed, args.loop, args.crossfade);
      write.metadata.emplace_back("ifsfx:loop", std::to_string(args.loop));
    }
    return write;
  };

  if (!textures.loop_closed() && !args.quiet)
    fmt::print(stderr,
               "ifsfx: note: the buffers did not come back to themselves within {} steps: the "
               "loop repeats, but its last step is not a V-variable step (another --seed may "
               "close)\n",
               textures.burn_in());
  const std::int64_t done =
      movie ? write_texture_movie(args, textures, output, first, last) : last - first + 1;

  // Frame j shows step s = j / K of the sequence crossfaded towards step s + 1 by (j mod K) / K.
  // The frames are written to temporary files and put in place together at the end: a run that
  // fails or is stopped leaves every existing frame file as it was.
  std::vector<OutputFile> written;
  for (int frame = first; frame <= last && !movie; ++frame) {
    const StepPosition position = position_of(frame);
    OutputFile file(path_of(frame), output);
    write_image(file, textures.frame_at(position),
                metadata(textures.burn_in() + static_cast<int>(position.step)));
    written.push_back(std::move(file));
  }
  commit_together(written);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!args.quiet)
    fmt::print("{} ({}, V = {}, {}x{}): {} steps, {} frame{} in {:.3f} s{} -> {}\n", name,
               to_string(args.mode), args.count, size.width, size.height, textures.steps_done(),
               done, done == 1 ? "" : "s", seconds,
               args.loop > 0 ? fmt::format(" (a loop of {})", args.loop) : "", args.output);
}

}  // namespace

void add_texture_command(CLI::App& app) {
  auto args = std::make_shared<TextureArgs>();
  auto* cmd = app.add_subcommand(
      "texture", "Render a V-variable superfractal texture (or a sequence) from a superIFS");
  cmd->add_option("superpreset", args->preset,
                  "SuperIFS: a shipped name (paper-fig4, carpet-lace, ...) or a .super.toml path")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output image (.png, .tif, .exr, .jpg); with --frames a pattern like "
                  "tex_%04d.png (one %d or %0Nd), numbered from 1, or a movie (.mp4, .webm, "
                  ".gif, .webp: GIF and WebP loop for ever)")
      ->required();
  auto* frames = cmd->add_option("--frames", args->frames,
                                 "Frames to write: a sequence of textures, one per further step "
                                 "(default: 1, or the --loop's length)")
                     ->capture_default_str();
  add_texture_options(*cmd, args);
  // Written by `ifsfx farm texture` into its shards' scripts.
  cmd->add_option("--frame-range", args->frame_range,
                  "Write only frames START:END (from 0) of the --frames sequence")
      ->group("");
  cmd->callback([args, frames] {
    if (frames->count() == 0 && args->loop > 0) args->frames = static_cast<int>(args->loop);
    run_texture(*args);
  });
}

}  // namespace ifsfx::app
