// SPDX-License-Identifier: Apache-2.0
#include "run/filter_run.h"

#include "run/movie_size.h"

#include <memory>
#include <string>

#include <fmt/format.h>

#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "run/arguments.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/image_sequence.h"
#include "video/window_sink.h"

namespace ifsfx::app {
namespace {

using engine::Animate;

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

// The output's size: --size or the frames'. 4:2:0 encoders need even sides: a movie's map is
// made at the nearest size that fits, so the whole picture is still shown, one pixel narrower or
// lower.
cv::Size output_size(const FilterArgs& args, cv::Size frame_size,
                     const std::function<void(const std::string&)>& note) {
  const cv::Size size = args.size.empty() ? frame_size : size_option(args.size);
  if (!writes_movie(args)) return size;
  return encodable_movie_size(args.output, args.codec, size, note);
}

// The output policy: no output file replaces an input (the movie, every file of an image
// sequence, the presets), whatever its spelling or links.
OutputOptions output_policy(const FilterArgs& args, const video::FrameSource& source,
                            const InputFiles& inputs) {
  OutputOptions output{.inputs = inputs};
  for (const auto& file : source.files()) output.inputs.add(file);
  add_preset_input(output.inputs, args.fractal.preset);
  add_preset_input(output.inputs, args.fractal.colouring);
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
                                            const FilterRun& run, video::FileSink*& movie) {
  if (args.preview)
    return std::make_unique<video::WindowSink>(
        fmt::format("ifsfx filter: {}", args.input),
        video::WindowSinkOptions{.fps = source.frame_rate().value(), .stop = run.stop});
  const OutputOptions output = output_policy(args, source, run.inputs);
  if (video::is_sequence_pattern(args.output))
    return std::make_unique<video::ImageSequenceSink>(
        args.output, video::ImageSequenceSinkOptions{
                         .expected = range.size_in(source.frame_count()), .output = output});
  auto file = open_movie(args, source, size, output);
  movie = file.get();
  return file;
}

}  // namespace

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

FilterOutcome filter_movie(const FilterArgs& args, const engine::FractalSettings& fractal,
                           const FilterRun& run) {
  const video::FrameRange range = check_filter_args(args);

  // The fractal is checked before any decoding; its maps wait for the frame size.
  engine::FractalSettings settings = fractal;
  settings.interpolation = args.interpolation;
  settings.animate = args.animate;
  settings.keyframe_interval = args.keyframe_interval;
  settings.superifs = args.superifs;
  settings.buffers = args.buffers;
  settings.sampling.cancel = CancelToken(run.stop);
  engine::FractalEngine engine(settings);

  video::silence_libav_log();
  std::unique_ptr<video::FrameSource> source = open_source(args);
  const cv::Size frame_size = source->size();
  const cv::Size size = output_size(args, frame_size, run.note);
  const video::Rational rate = source->frame_rate();
  video::FileSink* movie = nullptr;
  std::unique_ptr<video::FrameSink> sink = open_sink(args, *source, range, size, run, movie);

  engine.prepare(frame_size, size, rate.value());
  const video::FrameFilter filter = [&engine](const video::Frame& frame) {
    return engine.filter(frame.image, frame.index);
  };
  video::PipelineOptions options;
  options.range = range;
  options.stop = run.stop;
  options.progress = run.progress;
  options.progress_interval = run.progress_interval;
  // A stop while the steal map was computed is honoured by the map's own polling; one that came
  // just after it ends here, before any frame (the sink removes its temporary file).
  if (run.stop != nullptr && run.stop->load())
    throw Error(ErrorKind::interrupted, "interrupted before the first frame; nothing written");
  FilterOutcome out;
  out.result = video::run_pipeline(*source, *sink, filter, options);
  out.name = args.animate == Animate::superifs ? args.superifs : engine.name();
  out.size = size;
  out.rate = rate;
  out.stalls = engine.stalls();
  if (movie != nullptr && movie->timing() == video::FrameTiming::constant) {
    out.constant_rate = true;
    out.repeated = movie->frames_repeated();
    out.dropped = movie->frames_dropped();
  }
  return out;
}

}  // namespace ifsfx::app
