// SPDX-License-Identifier: Apache-2.0
// `ifsfx texture SUPERPRESET -o OUT`: a V-variable superfractal texture (paper §5, Fig. 4–5), or
// with --frames a sequence of them, one per further step, optionally crossfaded.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/option_groups.h"
#include "cli/stop_signals.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "run/texture_options.h"
#include "run/texture_run.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"

namespace ifsfx::app {
namespace {

void run_texture(const TextureArgs& args) {
  StopSignals signals;
  const TextureOutcome out = write_textures(
      load_superifs(args.preset), args,
      {.cancel = StopSignals::token(),
       .note = [](const std::string& line) { fmt::print(stderr, "ifsfx: {}\n", line); }});
  if (!out.loop_closed && !args.quiet)
    fmt::print(stderr,
               "ifsfx: note: the buffers did not come back to themselves within {} steps: the "
               "loop repeats, but its last step is not a V-variable step (another --seed may "
               "close)\n",
               out.burn_in);
  if (!args.quiet)
    fmt::print("{} ({}, V = {}, {}x{}): {} steps, {} frame{} in {:.3f} s{} -> {}\n", out.name,
               to_string(args.mode), args.count, out.size.width, out.size.height, out.steps_done,
               out.frames, out.frames == 1 ? "" : "s", out.seconds,
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
