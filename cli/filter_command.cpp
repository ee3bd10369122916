// SPDX-License-Identifier: Apache-2.0
// `ifsfx filter INPUT -o OUTPUT`: the fractal video filter (paper §6, Fig. 6). Every frame of a
// movie (or image sequence) is colour-stolen through the steal map of an IFS, computed once (or
// rebuilt as time goes on with --animate), on three threads: decode, filter, encode.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/option_groups.h"
#include "cli/progress_bar.h"
#include "cli/stop_signals.h"
#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "run/filter_options.h"
#include "run/filter_run.h"
#include "run/fractal_filter_options.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"
#include "video/window_sink.h"

namespace ifsfx::app {
namespace {

using engine::Animate;

// A stopped run says what it kept; a complete one prints its summary (unless --quiet).
void report_filter(const FilterArgs& args, const FilterOutcome& out) {
  const video::PipelineResult& result = out.result;
  const std::string where = args.preview ? std::string("the preview") : args.output;
  if (result.interrupted && !args.preview)
    throw Error(
        ErrorKind::interrupted,
        result.partial.empty()
            ? fmt::format("interrupted after {} frames; nothing written ({} left as it was)",
                          result.frames_written, where)
            : fmt::format("interrupted: {} frames kept in {} ({} left as it was)",
                          result.frames_written, result.partial.string(), where));
  // A constant-rate output repeats and drops frames by their times: say how many, as ffmpeg does.
  std::string retimed;
  if (out.constant_rate && (out.repeated > 0 || out.dropped > 0))
    retimed = fmt::format(" (constant {}/{} fps: {} repeated, {} dropped)", out.rate.num,
                          out.rate.den, out.repeated, out.dropped);
  if (!args.quiet)
    fmt::print("{}: {} frames {}x{} in {:.2f} s ({:.1f} fps){}{} -> {}\n", out.name,
               result.frames_written, out.size.width, out.size.height, result.seconds,
               result.frames_written / std::max(result.seconds, 1e-9),
               args.animate != Animate::none ? fmt::format(", {} map stalls", out.stalls) : "",
               retimed, where);
}

void run_filter(const FilterArgs& args) {
  check_filter_args(args);  // before the signals: a bad command line fails at once
  StopSignals signals;      // from here on, Ctrl-C and SIGTERM stop the command within 0.5 s
  FilterRun run;
  run.stop = &StopSignals::stop_flag();
  run.note = [](const std::string& line) { fmt::print(stderr, "ifsfx: {}\n", line); };
  const bool tty = isatty(fileno(stderr)) != 0;
  if (!args.quiet && !args.preview) {
    run.progress = [bar = ProgressBar(tty, "frames", "fps")](const video::Progress& p) {
      bar(p.done, p.total, p.seconds, p.finished);
    };
    run.progress_interval = tty ? 0.25 : 2.0;
  }
  // The fractal is loaded and checked before any decoding; its maps wait for the frame size.
  std::vector<std::string> warnings;
  const engine::FractalSettings fractal = args.fractal.settings(&warnings);
  for (const std::string& warning : warnings) run.note("warning: " + warning);
  report_filter(args, filter_movie(args, fractal, run));
}

}  // namespace

void add_filter_command(CLI::App& app) {
  auto args = std::make_shared<FilterArgs>();
  auto* cmd = app.add_subcommand(
      "filter", "Filter a movie (or image sequence) through a fractal: colour stealing per frame");
  cmd->add_option("input", args->input,
                  "Input movie (any file FFmpeg reads) or image sequence pattern (frame_%04d.png). "
                  "A phone clip's rotation (display matrix or rotate tag) is applied: frames are "
                  "turned upright before the filter, and the output is upright with no rotation "
                  "of its own")
      ->required();
  cmd->add_option(
      "-o,--output", args->output,
      "Output movie (.mp4, .mkv, .avi, ...) or image sequence pattern (frame_%04d.png); "
      "put in place when complete, never over an input; a run that fails or is "
      "stopped keeps its frames in OUTPUT-STEM.partial.EXT");
  cmd->add_flag("--preview", args->preview,
                "Show the result in a window instead of writing a file");
  add_filter_options(*cmd, args);
  cmd->add_option("--frames", args->frames,
                  "Source frames START:END to filter, both included, from 0 (START: or :END too); "
                  "frames are counted as the input gives them (the Nth picture, also in a "
                  "variable-rate movie), not by time");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress bar or summary");
  // Written by `ifsfx farm filter` into its shards' scripts; not for people.
  cmd->add_flag("--segment", args->segment,
                "A segment of a sharded run: the source's clock, no audio")
      ->group("");
  cmd->callback([args] { run_filter(*args); });
}

}  // namespace ifsfx::app
