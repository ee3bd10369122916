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

#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/filter_options.h"
#include "apps/fractal_filter_options.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/fractal_engine.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"
#include "video/window_sink.h"

namespace ifsfx::app {
namespace {

using video::Animate;

std::string clock_text(double seconds) {
  if (seconds < 0) return "--:--";
  const auto s = static_cast<long>(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{}:{:02}", s / 60, s % 60);
}

// The progress bar on a terminal (redrawn in place), or a plain line per report otherwise.
class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool tty) : tty_(tty) {}

  void operator()(const video::Progress& p) {
    const std::string counts = p.total >= 0 ? fmt::format("{}/{} frames", p.done, p.total)
                                            : fmt::format("{} frames", p.done);
    const std::string rate = fmt::format("{:.1f} fps", p.fps());
    if (tty_) {
      std::string bar;
      if (p.total > 0) {
        constexpr int width = 30;
        const auto filled =
            static_cast<int>(width * std::min<double>(1.0, static_cast<double>(p.done) / p.total));
        bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
              std::string(static_cast<std::size_t>(width - filled), '.') + "] ";
      }
      fmt::print(stderr, "\r{}{}  {}  ETA {}  ", bar, counts, rate, clock_text(p.eta()));
      if (p.finished) std::fputs("\n", stderr);
    } else {
      fmt::print(stderr, "{}  {}  elapsed {}  ETA {}\n", counts, rate, clock_text(p.seconds),
                 clock_text(p.eta()));
    }
    std::fflush(stderr);
  }

 private:
  bool tty_;
};

std::unique_ptr<video::FrameSource> open_source(const FilterArgs& args) {
  if (video::is_sequence_pattern(args.input))
    return std::make_unique<video::ImageSequenceSource>(
        args.input, video::ImageSequenceOptions{.fps = args.fps, .skip_gaps = args.skip_gaps});
  return std::make_unique<video::FileSource>(
      args.input, video::FileSourceOptions{.threads = args.fractal.engine.sampling.threads});
}

bool writes_movie(const FilterArgs& args) {
  return !args.output.empty() && !video::is_sequence_pattern(args.output);
}

// Cheap checks of the arguments and the output first: an unusable output fails before any
// decoding. Returns the frame range.
video::FrameRange check_filter_args(const FilterArgs& args) {
  if (args.preview == !args.output.empty())
    throw Error(ErrorKind::invalid_argument,
                "filter: give either -o OUTPUT or --preview (got both or neither)");
  if (args.preview) video::require_display("--preview", "write a file with -o instead");
  const video::FrameRange range =
      args.frames.empty() ? video::FrameRange{} : video::parse_frame_range(args.frames);
  video::check_output_name(args.output);
  const bool movie_output = writes_movie(args);
  if (movie_output) video::resolve_timing(args.output, args.codec, args.timing);
  if (args.segment && !movie_output)
    throw Error(ErrorKind::invalid_argument, "--segment: a farm segment is a movie file");
  check_filter_rules(args);
  if (args.timing_given && !movie_output)
    throw Error(ErrorKind::invalid_argument,
                "--fps-mode: only a movie output has frame times (got an image sequence or "
                "--preview)");
  return range;
}

// The output's size: --size or the frames'. 4:2:0 encoders need even sides: a movie's map is
// made at the nearest size that fits, so the whole picture is still shown, one pixel narrower or
// lower.
cv::Size output_size(const FilterArgs& args, cv::Size frame_size) {
  const cv::Size size = args.size.empty() ? frame_size : size_option(args.size);
  if (!writes_movie(args)) return size;
  const cv::Size fit = video::encodable_size(args.output, args.codec, size);
  if (fit != size)
    fmt::print(stderr,
               "ifsfx: note: {}: writing {}x{}, not {}x{}: {} codes colour at half resolution and "
               "needs even sides\n",
               args.output, fit.width, fit.height, size.width, size.height,
               video::resolve_encoder(args.output, args.codec));
  return fit;
}

// The output policy: no output file replaces an input (the movie, every file of an image
// sequence, the presets), whatever its spelling or links.
OutputOptions output_policy(const FilterArgs& args, const video::FrameSource& source) {
  OutputOptions output;
  for (const auto& file : source.files()) output.inputs.add(file);
  add_preset_input(output.inputs, args.fractal.engine.preset);
  add_preset_input(output.inputs, args.fractal.engine.colouring);
  if (args.animate == Animate::superifs) add_preset_input(output.inputs, args.superifs);
  return output;
}

std::unique_ptr<video::FileSink> open_movie(const FilterArgs& args,
                                            const video::FrameSource& source, cv::Size size,
                                            const OutputOptions& output) {
  video::FileSinkOptions o;
  o.codec = args.codec;
  o.size = size;
  o.frame_rate = source.frame_rate();
  o.time_base = source.time_base();
  o.timing = args.timing;
  o.threads = args.fractal.engine.sampling.threads;
  o.output = output;
  o.source_clock = args.segment;
  // A farm segment carries no audio: the join copies it once, from the input, as one run does.
  if (const auto audio = source.audio(); audio && !args.segment) {
    o.audio_from = audio->file;
    o.audio_origin = audio->origin;
  }
  return std::make_unique<video::FileSink>(args.output, o);
}

// Where the frames go: a window, an image sequence or a movie (also returned as `movie`).
std::unique_ptr<video::FrameSink> open_sink(const FilterArgs& args,
                                            const video::FrameSource& source,
                                            const video::FrameRange& range, cv::Size size,
                                            video::FileSink*& movie) {
  if (args.preview)
    return std::make_unique<video::WindowSink>(
        fmt::format("ifsfx filter: {}", args.input),
        video::WindowSinkOptions{.fps = source.frame_rate().value(),
                                 .stop = &StopSignals::stop_flag()});
  const OutputOptions output = output_policy(args, source);
  if (video::is_sequence_pattern(args.output))
    return std::make_unique<video::ImageSequenceSink>(
        args.output, video::ImageSequenceSinkOptions{
                         .expected = range.size_in(source.frame_count()), .output = output});
  auto file = open_movie(args, source, size, output);
  movie = file.get();
  return file;
}

video::PipelineOptions pipeline_options(const FilterArgs& args, const video::FrameRange& range) {
  video::PipelineOptions options;
  options.range = range;
  options.stop = &StopSignals::stop_flag();
  const bool tty = isatty(fileno(stderr)) != 0;
  if (!args.quiet && !args.preview) {
    options.progress = ProgressPrinter(tty);
    options.progress_interval = tty ? 0.25 : 2.0;
  }
  return options;
}

// A stopped run says what it kept; a complete one prints its summary (unless --quiet).
void report_filter(const FilterArgs& args, const video::FractalEngine& engine,
                   const video::PipelineResult& result, const video::FileSink* movie, cv::Size size,
                   video::Rational rate) {
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
  if (movie != nullptr && movie->timing() == video::FrameTiming::constant &&
      (movie->frames_repeated() > 0 || movie->frames_dropped() > 0))
    retimed = fmt::format(" (constant {}/{} fps: {} repeated, {} dropped)", rate.num, rate.den,
                          movie->frames_repeated(), movie->frames_dropped());
  if (!args.quiet)
    fmt::print("{}: {} frames {}x{} in {:.2f} s ({:.1f} fps){}{} -> {}\n",
               args.animate == Animate::superifs ? args.superifs : engine.name(),
               result.frames_written, size.width, size.height, result.seconds,
               result.frames_written / std::max(result.seconds, 1e-9),
               args.animate != Animate::none ? fmt::format(", {} map stalls", engine.stalls()) : "",
               retimed, where);
}

void run_filter(const FilterArgs& args) {
  const video::FrameRange range = check_filter_args(args);
  StopSignals signals;  // from here on, Ctrl-C and SIGTERM stop the command within 0.5 s

  // The fractal is loaded and checked before any decoding; its maps wait for the frame size.
  video::FractalSettings settings = args.fractal.settings();
  settings.interpolation = args.interpolation;
  settings.animate = args.animate;
  settings.keyframe_interval = args.keyframe_interval;
  settings.superifs = args.superifs;
  settings.buffers = args.buffers;
  video::FractalEngine engine(settings);
  print_warnings(engine.warnings());

  video::silence_libav_log();
  std::unique_ptr<video::FrameSource> source = open_source(args);
  const cv::Size frame_size = source->size();
  const cv::Size size = output_size(args, frame_size);
  const video::Rational rate = source->frame_rate();
  video::FileSink* movie = nullptr;
  std::unique_ptr<video::FrameSink> sink = open_sink(args, *source, range, size, movie);

  engine.prepare(frame_size, size, rate.value());
  const video::FrameFilter filter = [&engine](const video::Frame& frame) {
    return engine.filter(frame.image, frame.index);
  };
  const video::PipelineOptions options = pipeline_options(args, range);
  // Ctrl-C while the steal map was computed is honoured by the map's own polling; one that came
  // just after it ends here, before any frame (the sink removes its temporary file).
  if (StopSignals::stop_flag())
    throw Error(ErrorKind::interrupted, "interrupted before the first frame; nothing written");
  const video::PipelineResult result = video::run_pipeline(*source, *sink, filter, options);
  report_filter(args, engine, result, movie, size, rate);
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
