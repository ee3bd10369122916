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
#include "apps/fractal_filter_options.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "video/drift.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/fractal_filter.h"
#include "video/image_sequence.h"
#include "video/map_schedule.h"
#include "video/pipeline.h"
#include "video/window_sink.h"

namespace ifsfx::app {
namespace {

enum class Animate { none, drift, superifs };

struct FilterArgs {
  std::string input;
  std::string output;
  bool preview = false;
  FractalFilterArgs fractal{.preset = "barnsley-fern"};
  Interpolation interpolation = Interpolation::bilinear;
  std::string size;
  std::string codec;
  std::string frames;
  double fps = 25;
  Animate animate = Animate::none;
  int keyframe_interval = 12;
  std::string superifs = "paper-fig4";
  int buffers = 3;
  bool quiet = false;
};

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
      std::fputs(
          fmt::format("\r{}{}  {}  ETA {}  ", bar, counts, rate, clock_text(p.eta())).c_str(),
          stderr);
      if (p.finished) std::fputs("\n", stderr);
    } else {
      std::fputs(fmt::format("{}  {}  elapsed {}  ETA {}\n", counts, rate, clock_text(p.seconds),
                             clock_text(p.eta()))
                     .c_str(),
                 stderr);
    }
    std::fflush(stderr);
  }

 private:
  bool tty_;
};

std::unique_ptr<video::FrameSource> open_source(const FilterArgs& args) {
  if (video::is_sequence_pattern(args.input))
    return std::make_unique<video::ImageSequenceSource>(args.input,
                                                        video::ImageSequenceOptions{args.fps});
  return std::make_unique<video::FileSource>(
      args.input, video::FileSourceOptions{.threads = args.fractal.threads});
}

video::Rational rate_of(const video::FrameSource& source) {
  if (const auto* file = dynamic_cast<const video::FileSource*>(&source)) return file->frame_rate();
  const double fps = source.fps();
  if (std::abs(fps - std::round(fps)) < 1e-9) return {static_cast<int>(std::lround(fps)), 1};
  return {static_cast<int>(std::lround(fps * 1001)), 1001};
}

void check_distinct(const std::string& input, const std::string& output) {
  std::error_code ec;
  if (std::filesystem::exists(output, ec) && std::filesystem::equivalent(input, output, ec))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the output would overwrite the input", output));
}

void run_filter(const FilterArgs& args) {
  if (args.preview == !args.output.empty())
    throw Error(ErrorKind::invalid_argument,
                "filter: give either -o OUTPUT or --preview (got both or neither)");
  if (args.preview) video::require_display("--preview", "write a file with -o instead");
  const video::FrameRange range =
      args.frames.empty() ? video::FrameRange{} : video::parse_frame_range(args.frames, "--frames");
  video::FilterOptions filter_options = args.fractal.filter_options();
  filter_options.interpolation = args.interpolation;
  // Cheap checks of the output first: an unusable output fails before any decoding.
  if (!args.output.empty() && !video::is_sequence_pattern(args.output))
    video::resolve_encoder(args.output, args.codec);

  const IfsPreset F = load_preset(args.fractal.preset);
  const Ifs G = colouring_option(args.fractal.colouring, F.ifs);

  video::silence_libav_log();
  std::unique_ptr<video::FrameSource> source = open_source(args);
  const cv::Size frame_size = source->size();
  const cv::Size size = args.size.empty() ? frame_size : size_option(args.size);
  const video::Rational rate = rate_of(*source);

  StopSignals signals;
  std::unique_ptr<video::FrameSink> sink;
  if (args.preview) {
    sink = std::make_unique<video::WindowSink>(
        fmt::format("ifsfx filter: {}", args.input),
        video::WindowSinkOptions{.fps = rate.value(), .stop = &StopSignals::stop_flag()});
  } else {
    check_distinct(args.input, args.output);
    if (video::is_sequence_pattern(args.output)) {
      sink = std::make_unique<video::ImageSequenceSink>(args.output);
    } else {
      video::FileSinkOptions o;
      o.codec = args.codec;
      o.size = size;
      o.frame_rate = rate;
      o.threads = args.fractal.threads;
      if (const auto* file = dynamic_cast<const video::FileSource*>(source.get());
          file != nullptr && file->has_audio()) {
        o.audio_from = file->path();
        o.audio_origin = file->start_time();
      }
      sink = std::make_unique<video::FileSink>(args.output, o);
    }
  }

  StealMapOptions map_options = args.fractal.map_options();

  video::FrameFilter filter;
  std::unique_ptr<video::MapSchedule> schedule;
  std::shared_ptr<TextureSequence> sequence;
  const int interval = args.keyframe_interval;
  if (args.animate == Animate::none) {
    auto table = std::make_shared<const video::RemapTable>(
        video::make_remap_table(compute_steal_map(F.ifs, G, size, map_options), frame_size,
                                args.interpolation, args.fractal.threads));
    filter = [table, filter_options](const video::Frame& frame) {
      return video::filter_frame(frame.image, *table, filter_options);
    };
  } else if (args.animate == Animate::drift) {
    // Drift: keyframe k shows the IFS drifted to time k·K/fps, in a view fixed from the base IFS
    // so that the frame does not jump as the attractor moves.
    if (!map_options.view)
      map_options.view =
          fit_view(attractor_bounds(F.ifs, args.fractal.seed), size, args.fractal.margin);
    const video::DriftOptions drift = args.fractal.drift_options();
    video::drift(F.ifs, 0, drift);  // checks the drift options before any work
    const double fps = rate.value();
    schedule = std::make_unique<video::MapSchedule>(
        [=, base = F.ifs](std::int64_t k) {
          const Ifs now = video::drift(base, static_cast<double>(k) * interval / fps, drift);
          return video::make_remap_table(compute_steal_map(now, G, size, map_options), frame_size,
                                         args.interpolation, args.fractal.threads);
        },
        interval);
  } else {
    // superIFS: keyframe k is texture k of the V-variable sequence (paper §5, eq. 14), one step
    // per keyframe after the burn-in — a pure function of k and the seed.
    TextureOptions t;
    t.count = args.buffers;
    t.mode = TextureMode::steal;
    t.source = cv::Mat(frame_size, CV_8UC3);  // only its size: it sets the descent depth
    t.seed = args.fractal.seed;
    t.threads = args.fractal.threads;
    sequence = std::make_shared<TextureSequence>(load_superifs(args.superifs).super, size, t);
    schedule = std::make_unique<video::MapSchedule>(
        [=, seq = sequence](std::int64_t k) {
          return video::make_remap_table(seq->map_at(k), frame_size, args.interpolation,
                                         args.fractal.threads);
        },
        interval);
  }
  if (schedule) {
    filter = [s = schedule.get(), filter_options](const video::Frame& frame) {
      const video::MapSchedule::Blend b = s->at(frame.index);
      return video::filter_frame(frame.image, *b.from, *b.to, b.t, filter_options);
    };
  }

  video::PipelineOptions options;
  options.range = range;
  options.stop = &StopSignals::stop_flag();
  const bool tty = isatty(fileno(stderr)) != 0;
  if (!args.quiet && !args.preview) {
    options.progress = ProgressPrinter(tty);
    options.progress_interval = tty ? 0.25 : 2.0;
  }
  // Ctrl-C while the steal map was computed: nothing to keep (the sink removes its .part file).
  if (StopSignals::stop_flag())
    throw Error(ErrorKind::interrupted, "interrupted before the first frame; nothing written");
  const video::PipelineResult result = video::run_pipeline(*source, *sink, filter, options);
  const std::string where = args.preview ? std::string("the preview") : args.output;
  if (result.interrupted && !args.preview)
    throw Error(ErrorKind::interrupted,
                fmt::format("interrupted: {} frames written to {}", result.frames_written, where));
  if (!args.quiet)
    std::printf(
        "%s\n",
        fmt::format("{}: {} frames {}x{} in {:.2f} s ({:.1f} fps){} -> {}",
                    args.animate == Animate::superifs ? args.superifs : F.ifs.name,
                    result.frames_written, size.width, size.height, result.seconds,
                    result.frames_written / std::max(result.seconds, 1e-9),
                    schedule ? fmt::format(", {} map stalls", schedule->stalls()) : "", where)
            .c_str());
}

}  // namespace

void add_filter_command(CLI::App& app) {
  auto args = std::make_shared<FilterArgs>();
  auto* cmd = app.add_subcommand(
      "filter", "Filter a movie (or image sequence) through a fractal: colour stealing per frame");
  cmd->add_option("input", args->input,
                  "Input movie (any file FFmpeg reads) or image sequence pattern (frame_%04d.png)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output movie (.mp4, .mkv, .avi, ...) or image sequence pattern; written as "
                  "OUTPUT.part and renamed at the end");
  cmd->add_flag("--preview", args->preview,
                "Show the result in a window instead of writing a file");
  add_fractal_filter_options(*cmd, args->fractal);
  const std::map<std::string, Interpolation> interpolations{{"bilinear", Interpolation::bilinear},
                                                            {"nearest", Interpolation::nearest}};
  cmd->add_option("--interpolation", args->interpolation,
                  "Lookup in the frame: bilinear or nearest")
      ->transform(choice(interpolations))
      ->default_str("bilinear")
      ->option_text(choices_text(interpolations, "bilinear"));
  cmd->add_option("--size", args->size, "Output size WxH (default: the input's)");
  cmd->add_option("--codec", args->codec,
                  "Video encoder (libx264, h264, mpeg4, ffv1, ...; default by container: "
                  ".mp4/.mkv H.264 CRF 23, .avi MPEG-4 part 2)");
  cmd->add_option("--frames", args->frames,
                  "Source frames START:END to filter, both included, from 0 (START: or :END too)");
  cmd->add_option("--fps", args->fps, "Frame rate of an image sequence input")
      ->capture_default_str();
  const std::map<std::string, Animate> animations{
      {"none", Animate::none}, {"drift", Animate::drift}, {"superifs", Animate::superifs}};
  cmd->add_option("--animate", args->animate,
                  "none: one fixed map; drift: map coefficients wander by fBm noise; superifs: a "
                  "V-variable step of --superifs per keyframe")
      ->transform(choice(animations))
      ->default_str("none")
      ->option_text(choices_text(animations, "none"))
      ->group("Animation");
  cmd->add_option("--keyframe-interval", args->keyframe_interval,
                  "Animation: frames between rebuilt maps, cross-faded in between")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000))
      ->group("Animation");
  cmd->add_option("--superifs", args->superifs,
                  "--animate superifs: the superIFS (shipped name or .toml path); its own view and "
                  "colouring replace --preset, --colouring and --view")
      ->capture_default_str()
      ->group("Animation");
  cmd->add_option("--buffers", args->buffers, "--animate superifs: V, the number of buffers")
      ->capture_default_str()
      ->check(CLI::Range(1, 64))
      ->group("Animation");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress bar or summary");
  cmd->callback([args] { run_filter(*args); });
}

}  // namespace ifsfx::app
