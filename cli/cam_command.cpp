// SPDX-License-Identifier: Apache-2.0
// `ifsfx cam`: the live kaleidoscope of paper §6 (Fig. 6, bottom right) — a V4L2 camera coloured
// through a steal map computed once, shown in a window, sent to a V4L2 output device (a virtual
// webcam for any app), recorded to a movie file, or all three.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cam_controls.h"
#include "cli/cam_recording.h"
#include "cli/cam_window.h"
#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/option_groups.h"
#include "cli/stop_signals.h"
#include "ifs/error.h"
#include "run/fractal_filter_options.h"
#include "video/camera_pipeline.h"
#include "video/file_sink.h"
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
    fmt::print("  {} {:<4} {}{}{}\n", direction, video::fourcc_name(f.fourcc), f.description,
               sizes.empty() ? "" : ": ", sizes);
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
      fmt::print("{}: cannot query: {}\n", e.info.path, e.error);
      continue;
    }
    const video::V4l2DeviceInfo& d = e.info;
    fmt::print("{}: {} ({}, {}){}{}\n", d.path, d.card, d.driver, d.bus,
               d.capture ? ", capture" : "", d.output ? ", output" : "");
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

// Fails on a bad output path, pattern or display before the camera is opened and the map
// computed (but says "no camera" first when there is none). Returns the device.
std::string check_cam_args(const CamArgs& args, bool window) {
  video::check_output_name(args.record, "--record");
  if (!args.record.empty()) video::resolve_encoder(args.record, args.codec);
  engine::check_filter_options(
      {.mix = args.fractal.settings().mix});  // --view, --background, --mix
  try {
    video::sequence_path(args.snapshot, 1);
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("--snapshot: {}", e.what()));
  }
  std::string device = args.device.empty() ? default_device() : args.device;
  if (window) video::require_display("--window", "run headless with --output or --record");
  return device;
}

video::V4l2CaptureOptions capture_options(const CamArgs& args, cv::Size size) {
  video::V4l2CaptureOptions copt;
  copt.size = size;
  copt.fps = args.fps;
  copt.buffers = args.buffers;
  if (!args.format.empty()) copt.formats = {video::parse_pixel_format(args.format, "--format")};
  return copt;
}

// The output policy: a recording never replaces an input (the devices, the presets).
OutputOptions cam_output_policy(const CamArgs& args, const std::string& device) {
  OutputOptions output;
  for (const std::string& input :
       {device, args.output, args.fractal.preset, args.fractal.colouring})
    add_preset_input(output.inputs, input);
  if (!args.record.empty()) check_output(args.record, output);
  return output;
}

// --output: the virtual webcam, or nothing.
std::unique_ptr<video::V4l2Output> open_webcam(const CamArgs& args, cv::Size size, double fps) {
  if (args.output.empty()) return nullptr;
  return std::make_unique<video::V4l2Output>(
      args.output, size,
      video::V4l2OutputOptions{
          .format = video::parse_pixel_format(args.output_format, "--output-format"), .fps = fps});
}

// The window's part of each frame: the readout, the keys. Sets `quit` when the window is closed
// (or q, Esc) and ends the session; without a window, every frame goes on.
video::CameraObserver window_observer(CamWindow* win, CamControls& controls,
                                      const CamRecording& recording, const Notices& notice,
                                      bool& quit) {
  return [win, &controls, &recording, &notice, &quit](const Frame& out, const CameraStats& stats) {
    if (win == nullptr) return true;
    controls.poll();
    const LiveFilter& filter = controls.filter();
    const std::string readout =
        fmt::format("{:.1f} fps  {}{}{}", stats.fps(), filter.name(),
                    filter.animated() ? "  drift" : "", recording.recording() ? "  REC" : "");
    const int key = win->show(out.image, {readout, notice.current()});
    if (key == 'q' || key == 27 /* Esc */ || key == CamWindow::kClosed) {
      quit = true;
      return false;
    }
    controls.key(key, out.image);
    return true;
  };
}

// The session; a fault ends the recording as a partial movie beside its target (left as it was)
// and says so.
CameraStats run_session(video::V4l2Capture& camera, CamControls& controls,
                        const std::vector<FrameSink*>& sinks, const CamRecording& recording,
                        const video::CameraLoopOptions& options,
                        const video::CameraObserver& observer) {
  try {
    return video::run_camera(
        camera, [&](const Frame& frame) { return controls.filter()(frame); }, sinks, options,
        observer);
  } catch (const Error& e) {
    if (!recording.partial().empty()) {
      throw Error(e.kind(), fmt::format("{}; recording kept: {} ({} frames; {} left as it was)",
                                        e.what(), recording.partial().string(), recording.frames(),
                                        recording.path().string()));
    }
    throw;
  }
}

// The summary (unless --quiet); a session stopped by a signal, not by the window, is an error.
void report_cam(const CamArgs& args, const CameraStats& stats, const CamControls& controls,
                const CamRecording& recording, bool stopped) {
  const std::int64_t drift_maps = controls.drift_maps();
  const std::string kept =
      recording.frames() > 0
          ? fmt::format("; recorded {} ({} frames)", recording.path().string(), recording.frames())
          : "";
  if (!args.quiet) {
    fmt::print(stderr,
               "cam: {} frames in {:.2f} s ({:.1f} fps), {} dropped ({:.1f}%), latency mean "
               "{:.1f} ms, p95 {:.1f} ms{}{}\n",
               stats.frames, stats.seconds, stats.fps(), stats.dropped, 100 * stats.drop_fraction(),
               1e3 * stats.latency_mean, 1e3 * stats.latency_p95,
               drift_maps > 0 ? fmt::format(", {} drift maps", drift_maps) : "", kept);
  }
  if (stopped) {
    throw Error(ErrorKind::interrupted,
                fmt::format("cam: interrupted after {} frames{}", stats.frames, kept));
  }
}

void run_cam(const CamArgs& args) {
  if (args.list) {
    list_devices();
    return;
  }
  const cv::Size size = size_option(args.size);
  const bool window = args.window || (args.output.empty() && args.record.empty());
  StopSignals signals;  // from here on, Ctrl-C and SIGTERM end the session
  const std::string device = check_cam_args(args, window);

  video::V4l2Capture camera(device, capture_options(args, size));
  const cv::Size granted = camera.size();
  const double fps = camera.fps() > 0 ? camera.fps() : args.fps;
  if (!args.quiet) {
    fmt::print(stderr, "cam: {} ({}): {}x{} {} at {:g} fps\n", device, camera.card(), granted.width,
               granted.height, video::fourcc_name(video::fourcc(camera.format())), fps);
  }
  const OutputOptions output = cam_output_policy(args, device);

  // The starting map first: a preset that does not load fails before any output is opened.
  CamRecording recording(args.record.empty() ? "cam-recording.mkv" : args.record,
                         !args.record.empty(), args.codec, granted, fps, output);
  Notices notice(args.quiet);
  CamControls controls({.fractal = &args.fractal,
                        .fade_frames = args.fade_frames,
                        .size = granted,
                        .fps = fps,
                        .snapshot = args.snapshot,
                        .animate = args.animate == Animate::drift},
                       recording, notice);

  std::vector<FrameSink*> sinks;
  const std::unique_ptr<video::V4l2Output> webcam = open_webcam(args, granted, fps);
  if (webcam) sinks.push_back(webcam.get());
  if (!args.record.empty()) recording.start();
  sinks.push_back(&recording);

  std::unique_ptr<CamWindow> win;
  if (window) win = std::make_unique<CamWindow>();
  bool quit = false;
  std::atomic<bool>& stop = StopSignals::stop_flag();
  const CameraStats stats = run_session(
      camera, controls, sinks, recording, {.max_frames = args.max_frames, .stop = &stop},
      window_observer(win.get(), controls, recording, notice, quit));
  report_cam(args, stats, controls, recording, stop.load() && !quit);
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
  cmd->add_option("--fps", args->fps, "Requested frame rate")
      ->capture_default_str()
      ->check(number_in(0, 1000, true));
  cmd->add_option("--format", args->format,
                  "Capture pixel format: yuyv, mjpeg, nv12, yuv420, uyvy, rgb24, bgr24 "
                  "(default: the best the camera offers at --size and --fps)");
  cmd->add_option("--buffers", args->buffers, "Driver buffers (fewer = lower latency)")
      ->capture_default_str()
      ->check(CLI::Range(2, 32));
  cmd->add_option("--max-frames", args->max_frames, "Stop after N frames (0 = until quit)")
      ->capture_default_str()
      ->check(not_negative());
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
