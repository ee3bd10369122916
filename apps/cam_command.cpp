// `ifsfx cam`: the live kaleidoscope of paper §6 (Fig. 6, bottom right) — a V4L2 camera coloured
// through a steal map computed once, shown in a window, sent to a V4L2 output device (a virtual
// webcam for any app), recorded to a movie file, or all three.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/cam_recording.h"
#include "apps/cam_window.h"
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/fractal_filter_options.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "video/camera_drift.h"
#include "video/camera_pipeline.h"
#include "video/file_sink.h"
#include "video/fractal_filter.h"
#include "video/image_sequence.h"
#include "video/v4l2_capture.h"
#include "video/v4l2_device.h"
#include "video/v4l2_output.h"
#include "video/window_sink.h"

namespace ifsfx::app {
namespace {

using video::CameraStats;
using video::Frame;
using video::FrameSink;

enum class Animate { none, drift };

struct CamArgs {
  bool list = false;
  std::string device;
  std::string size = "640x480";
  double fps = 30;
  std::string format;
  int buffers = 3;
  std::int64_t max_frames = 0;
  std::string output;
  std::string output_format = "yuyv";
  std::string record;
  std::string codec;
  bool window = false;
  std::string snapshot = "cam-snapshot-%03d.png";
  FractalFilterArgs fractal{.preset = "sierpinski-triangle"};
  Animate animate = Animate::none;
  int fade_frames = 12;
  bool quiet = false;
};

std::string rate_list(const std::vector<double>& fps, bool stepwise) {
  if (fps.empty()) return "";
  if (stepwise) return fmt::format(" ({:g}-{:g} fps)", fps.back(), fps.front());
  std::string s;
  for (double f : fps) s += (s.empty() ? "" : ", ") + fmt::format("{:g}", f);
  return " (" + s + " fps)";
}

void print_formats(const char* direction, const std::vector<video::V4l2Format>& formats) {
  for (const video::V4l2Format& f : formats) {
    std::string sizes;
    for (const video::V4l2FrameSize& s : f.sizes) {
      sizes += fmt::format("{}{}x{}{}", sizes.empty() ? "" : (f.stepwise_sizes ? " to " : ", "),
                           s.size.width, s.size.height, rate_list(s.fps, s.stepwise_rates));
    }
    std::printf("%s\n", fmt::format("  {} {:<4} {}{}{}", direction, video::fourcc_name(f.fourcc),
                                    f.description, sizes.empty() ? "" : ": ", sizes)
                            .c_str());
  }
}

void list_devices() {
  const auto devices = video::list_v4l2_devices();
  if (devices.empty()) {
    std::printf("no V4L2 video devices under /dev: no camera connected\n");
    return;
  }
  for (const video::V4l2ListEntry& e : devices) {
    if (!e.error.empty()) {
      std::printf("%s\n", fmt::format("{}: cannot query: {}", e.info.path, e.error).c_str());
      continue;
    }
    const video::V4l2DeviceInfo& d = e.info;
    std::printf("%s\n", fmt::format("{}: {} ({}, {}){}{}", d.path, d.card, d.driver, d.bus,
                                    d.capture ? ", capture" : "", d.output ? ", output" : "")
                            .c_str());
    print_formats("capture", d.capture_formats);
    print_formats("output ", d.output_formats);
  }
}

// The first capture device, or a one-line error saying there is no camera.
std::string default_device() {
  for (const video::V4l2ListEntry& e : video::list_v4l2_devices()) {
    if (e.error.empty() && e.info.capture && !e.info.output) return e.info.path;
  }
  throw Error(ErrorKind::not_found,
              "cam: no camera found (no V4L2 capture device under /dev); connect one or name "
              "it with --device");
}

// The live filter: F coloured through G on the camera's frame size (DESIGN.md §3) — one steal
// map computed once and reapplied per frame, or, animated, maps of F drifting in time built on a
// worker and cross-faded in (video/camera_drift.h).
class LiveFilter {
 public:
  LiveFilter(const CamArgs& args, const std::string& preset, cv::Size size, bool animate)
      : args_(args), size_(size) {
    const IfsPreset F = load_ifs(preset);
    F_ = F.ifs;
    name_ = F.ifs.name.empty() ? preset : F.ifs.name;
    G_ = colouring_option(args.fractal.colouring, F_);
    map_options_ = args.fractal.map_options();
    options_ = args.fractal.filter_options();
    fixed_ = video::make_remap_table(compute_steal_map(F_, G_, size, map_options_), size,
                                     Interpolation::bilinear, args.fractal.threads);
    set_animate(animate);
  }

  const std::string& name() const { return name_; }
  bool animated() const { return drift_ != nullptr; }

  void set_animate(bool on) {
    if (!on) {
      drift_.reset();
      return;
    }
    if (drift_) return;
    video::LiveDriftOptions o;
    o.drift = args_.fractal.drift_options();
    o.map = map_options_;
    o.fade_frames = args_.fade_frames;
    drift_ = std::make_unique<video::LiveDrift>(F_, G_, size_, o);
  }

  cv::Mat operator()(const Frame& frame) {
    if (!drift_) return video::filter_frame(frame.image, fixed_, options_);
    return drift_->filter(frame.image, frame.timestamp, options_);
  }

  std::int64_t maps_built() const { return drift_ ? drift_->maps_built() : 0; }

 private:
  const CamArgs& args_;
  cv::Size size_;
  Ifs F_, G_;
  std::string name_;
  StealMapOptions map_options_;
  video::FilterOptions options_;
  video::RemapTable fixed_;
  std::unique_ptr<video::LiveDrift> drift_;
};

// The shipped presets the n/p keys step through: the drawing IFSs (the factor-1 square tilings
// are colouring IFSs only and are refused as F).
std::vector<std::string> cycle_presets() {
  std::vector<std::string> names;
  for (const PresetSummary& p : list_shipped_presets()) {
    if (p.contraction < 1) names.push_back(p.name);
  }
  return names;
}

// The first file of the --snapshot pattern, counting from 1, that does not exist yet.
std::filesystem::path next_snapshot(const std::string& pattern) {
  for (std::int64_t n = 1;; ++n) {
    std::filesystem::path p = video::sequence_path(pattern, n);
    if (!std::filesystem::exists(p)) return p;
  }
}

// Reports what the window's keys did: on stderr (unless --quiet) and, for a few seconds, in the
// window's readout.
class Notices {
 public:
  explicit Notices(bool quiet) : quiet_(quiet) {}
  void operator()(const std::string& text) {
    if (!quiet_) std::fprintf(stderr, "cam: %s\n", text.c_str());
    text_ = text;
    until_ = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  }
  // The latest notice while it is fresh, else "".
  std::string current() const {
    return std::chrono::steady_clock::now() < until_ ? text_ : std::string();
  }

 private:
  bool quiet_;
  std::string text_;
  std::chrono::steady_clock::time_point until_;
};

void run_cam(const CamArgs& args) {
  if (args.list) {
    list_devices();
    return;
  }
  const cv::Size size = size_option(args.size);
  if (args.fps <= 0 || args.fps > 1000) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--fps: must be in (0, 1000] (got {:g})", args.fps));
  }
  const bool window = args.window || (args.output.empty() && args.record.empty());
  // Fail on a bad output path, pattern or display before the camera is opened and the map
  // computed (but say "no camera" first when there is none).
  if (!args.record.empty()) video::resolve_encoder(args.record, args.codec);
  args.fractal.map_options();     // --view
  args.fractal.filter_options();  // --mix, --background
  try {
    video::sequence_path(args.snapshot, 1);
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("--snapshot: {}", e.what()));
  }
  const std::string device = args.device.empty() ? default_device() : args.device;
  if (window) video::require_display("--window", "run headless with --output or --record");

  video::V4l2CaptureOptions copt;
  copt.size = size;
  copt.fps = args.fps;
  copt.buffers = args.buffers;
  if (!args.format.empty()) copt.formats = {video::parse_pixel_format(args.format)};
  video::V4l2Capture camera(device, copt);
  const cv::Size granted = camera.size();
  const double fps = camera.fps() > 0 ? camera.fps() : args.fps;
  if (!args.quiet) {
    std::fprintf(
        stderr, "%s\n",
        fmt::format("cam: {} ({}): {}x{} {} at {:g} fps", device, camera.card(), granted.width,
                    granted.height, video::fourcc_name(video::fourcc(camera.format())), fps)
            .c_str());
  }

  auto filter = std::make_unique<LiveFilter>(args, args.fractal.preset, granted,
                                             args.animate == Animate::drift);

  std::vector<FrameSink*> sinks;
  std::unique_ptr<video::V4l2Output> webcam;
  if (!args.output.empty()) {
    webcam = std::make_unique<video::V4l2Output>(
        args.output, granted,
        video::V4l2OutputOptions{
            .format = video::parse_pixel_format(args.output_format, "--output-format"),
            .fps = fps});
    sinks.push_back(webcam.get());
  }
  CamRecording recording(args.record.empty() ? "cam-recording.mkv" : args.record,
                         !args.record.empty(), args.codec, granted, fps);
  if (!args.record.empty()) recording.start();
  sinks.push_back(&recording);

  std::unique_ptr<CamWindow> win;
  if (window) win = std::make_unique<CamWindow>();
  const std::vector<std::string> presets = cycle_presets();
  std::optional<std::size_t> preset_index;
  for (std::size_t i = 0; i < presets.size(); ++i) {
    if (presets[i] == args.fractal.preset) preset_index = i;
  }
  Notices notice(args.quiet);
  bool quit = false;
  std::int64_t drift_maps = 0;  // built by animations that have ended (a preset change, the a key)

  // n/p: the next/previous shipped preset. Its map is computed on a worker while the current
  // filter stays live (a map takes several frame intervals); the new filter takes over between
  // two frames once ready. Keys pressed meanwhile pick the preset to go to after it.
  bool animate = args.animate == Animate::drift;
  struct Switch {
    std::size_t index;
    std::future<std::unique_ptr<LiveFilter>> filter;
  };
  std::optional<Switch> pending;
  std::optional<std::size_t> wanted;
  const auto start_switch = [&](std::size_t i) {
    notice(fmt::format("computing the map of {}", presets[i]));
    pending =
        Switch{i, std::async(std::launch::async, [&args, name = presets[i], granted, animate] {
                 return std::make_unique<LiveFilter>(args, name, granted, animate);
               })};
  };
  const auto step_preset = [&](bool forward) {
    if (presets.empty()) return;
    const std::size_t n = presets.size();
    std::size_t i = wanted    ? *wanted
                    : pending ? pending->index
                              : preset_index.value_or(forward ? n - 1 : 0);
    i = forward ? (i + 1) % n : (i + n - 1) % n;
    if (pending) {
      wanted = i;
    } else {
      start_switch(i);
    }
  };
  const auto finish_switch = [&] {
    using namespace std::chrono_literals;
    if (!pending || pending->filter.wait_for(0s) != std::future_status::ready) return;
    const std::size_t i = pending->index;
    preset_index = i;  // also when it failed: n and p go on from there
    try {
      std::unique_ptr<LiveFilter> next = pending->filter.get();
      next->set_animate(animate);
      drift_maps += filter->maps_built();
      filter = std::move(next);
      notice(fmt::format("preset {} ({}/{})", presets[i], i + 1, presets.size()));
    } catch (const Error& e) {
      notice(fmt::format("preset {} not shown: {}", presets[i], e.what()));
    }
    pending.reset();
    if (wanted) {
      start_switch(*wanted);
      wanted.reset();
    }
  };
  // A failed snapshot or recording start is reported and the live view goes on: the session is
  // worth more than one file.
  const auto snapshot = [&](const cv::Mat& image) {
    try {
      const std::filesystem::path path = next_snapshot(args.snapshot);
      write_image(path, image);
      notice(fmt::format("snapshot {}", path.string()));
    } catch (const Error& e) {
      notice(fmt::format("snapshot failed: {}", e.what()));
    }
  };
  const auto toggle_recording = [&] {
    if (recording.recording()) {
      recording.stop();
      notice(fmt::format("recording stopped: {} ({} frames)", recording.path().string(),
                         recording.frames()));
      return;
    }
    try {
      recording.start();
      notice(fmt::format("recording {}", recording.path().string()));
    } catch (const Error& e) {
      notice(fmt::format("recording failed: {}", e.what()));
    }
  };

  const auto observer = [&](const Frame& out, const CameraStats& stats) {
    if (!win) return true;
    finish_switch();
    const std::string readout =
        fmt::format("{:.1f} fps  {}{}{}", stats.fps(), filter->name(),
                    filter->animated() ? "  drift" : "", recording.recording() ? "  REC" : "");
    switch (win->show(out.image, {readout, notice.current()})) {
      case 'q':
      case 27:  // Esc
      case CamWindow::kClosed:
        quit = true;
        return false;
      case 'n':
        step_preset(true);
        break;
      case 'p':
        step_preset(false);
        break;
      case 'a':
        animate = !animate;
        drift_maps += filter->maps_built();
        filter->set_animate(animate);
        notice(animate ? "animation on (drift)" : "animation off");
        break;
      case 's':
        snapshot(out.image);
        break;
      case 'r':
        toggle_recording();
        break;
      default:
        break;
    }
    return true;
  };

  StopSignals signals;
  std::atomic<bool>& stop = StopSignals::stop_flag();
  CameraStats stats;
  try {
    stats = video::run_camera(
        camera, [&](const Frame& frame) { return (*filter)(frame); }, sinks,
        {.max_frames = args.max_frames, .stop = &stop}, observer);
  } catch (const Error& e) {
    if (recording.frames() > 0) {
      throw Error(e.kind(), fmt::format("{}; recording kept: {} ({} frames)", e.what(),
                                        recording.path().string(), recording.frames()));
    }
    throw;
  }
  drift_maps += filter->maps_built();
  const std::string kept =
      recording.frames() > 0
          ? fmt::format("; recorded {} ({} frames)", recording.path().string(), recording.frames())
          : "";
  if (!args.quiet) {
    std::fprintf(
        stderr, "%s\n",
        fmt::format("cam: {} frames in {:.2f} s ({:.1f} fps), {} dropped ({:.1f}%), "
                    "latency mean {:.1f} ms, p95 {:.1f} ms{}{}",
                    stats.frames, stats.seconds, stats.fps(), stats.dropped,
                    100 * stats.drop_fraction(), 1e3 * stats.latency_mean, 1e3 * stats.latency_p95,
                    drift_maps > 0 ? fmt::format(", {} drift maps", drift_maps) : "", kept)
            .c_str());
  }
  if (stop.load() && !quit) {
    throw Error(ErrorKind::interrupted,
                fmt::format("cam: interrupted after {} frames{}", stats.frames, kept));
  }
}

}  // namespace

void add_cam_command(CLI::App& app) {
  auto args = std::make_shared<CamArgs>();
  auto* cmd = app.add_subcommand(
      "cam", "Live fractal kaleidoscope from a V4L2 camera: window, virtual webcam, recording");
  cmd->add_flag("--list", args->list, "List V4L2 devices with their formats, sizes and rates");
  cmd->add_option("--device", args->device,
                  "Camera device node (default: the first V4L2 capture device)");
  cmd->add_option("--size", args->size, "Requested capture size WxH (the camera may grant another)")
      ->capture_default_str();
  cmd->add_option("--fps", args->fps, "Requested frame rate")->capture_default_str();
  cmd->add_option("--format", args->format,
                  "Capture pixel format: yuyv, mjpeg, nv12, yuv420, uyvy, rgb24, bgr24 "
                  "(default: the best the camera offers at --size and --fps)");
  cmd->add_option("--buffers", args->buffers, "Driver buffers (fewer = lower latency)")
      ->capture_default_str()
      ->check(CLI::Range(2, 32));
  cmd->add_option("--max-frames", args->max_frames, "Stop after N frames (0 = until quit)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("-o,--output", args->output,
                  "V4L2 output device, e.g. a v4l2loopback node /dev/video10 (virtual webcam)");
  cmd->add_option("--output-format", args->output_format,
                  "Pixel format of --output: yuyv or yuv420")
      ->capture_default_str();
  cmd->add_option("--record", args->record, "Record the filtered frames to a movie file");
  cmd->add_option("--codec", args->codec, "Encoder of --record (default: the container's)");
  cmd->add_flag("--window", args->window,
                "Show a window (default when neither --output nor --record is given). Keys: n/p "
                "next/previous preset, a animation on/off, s snapshot, r start/stop recording, "
                "q/Esc quit");
  cmd->add_option("--snapshot", args->snapshot,
                  "File pattern of the window's snapshots (s key), numbered from 1 on; the first "
                  "free number is taken")
      ->capture_default_str();
  add_fractal_filter_options(*cmd, args->fractal);
  const std::map<std::string, Animate> animations{{"none", Animate::none},
                                                  {"drift", Animate::drift}};
  cmd->add_option("--animate", args->animate,
                  "none: one fixed map; drift: map coefficients wander by fBm noise (the window's "
                  "a key toggles it)")
      ->transform(choice(animations))
      ->default_str("none")
      ->option_text(choices_text(animations, "none"))
      ->group("Animation");
  cmd->add_option("--fade-frames", args->fade_frames,
                  "Animation: frames over which each new map fades in (maps are built as fast as "
                  "the machine allows, never holding up the camera)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000))
      ->group("Animation");
  cmd->add_flag("-q,--quiet", args->quiet, "Do not print the device and summary lines");
  cmd->callback([args] { run_cam(*args); });
}

}  // namespace ifsfx::app
