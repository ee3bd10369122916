// SPDX-License-Identifier: Apache-2.0
#include "tests/obs/obs_harness.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <obs-module.h>
#include <obs-nix-platform.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
// Last: Xlib defines None, Bool and Status as macros.
#include <X11/Xlib.h>

namespace ifsfx::obs_test {
namespace {

namespace fs = std::filesystem;

void* create_source(obs_data_t*, obs_source_t* source) {
  return source;
}
void destroy_nothing(void*) {}

obs_source_frame* probe_video(void*, obs_source_frame* frame) {
  Obs::get().capture().add(*frame);
  return frame;
}

void register_test_types() {
  obs_source_info source{};
  source.id = "ifsfx_test_source";
  source.type = OBS_SOURCE_TYPE_INPUT;
  source.output_flags = OBS_SOURCE_ASYNC_VIDEO;
  source.get_name = [](void*) { return "ifsfx test source"; };
  source.create = create_source;
  source.destroy = destroy_nothing;
  obs_register_source(&source);
  obs_source_info probe{};
  probe.id = "ifsfx_test_probe";
  probe.type = OBS_SOURCE_TYPE_FILTER;
  probe.output_flags = OBS_SOURCE_ASYNC_VIDEO;
  probe.get_name = [](void*) { return "ifsfx test probe"; };
  probe.create = create_source;
  probe.destroy = destroy_nothing;
  probe.filter_video = probe_video;
  obs_register_source(&probe);
}

void on_output(void* param, video_data* frame) {
  auto* self = static_cast<Obs*>(param);
  const cv::Mat picture(kHeight, kWidth, CV_8UC4, frame->data[0], frame->linesize[0]);
  self->set_output(picture);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

Paths& paths() {
  static Paths p;
  return p;
}

void Capture::add(const obs_source_frame& frame) {
  Planes p;
  p.format = frame.format;
  p.timestamp = frame.timestamp;
  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  if (frame.format == VIDEO_FORMAT_NV12) {
    p.planes = {cv::Mat(h, w, CV_8UC1, frame.data[0], frame.linesize[0]).clone(),
                cv::Mat(h / 2, w / 2, CV_8UC2, frame.data[1], frame.linesize[1]).clone()};
  } else {
    p.planes = {cv::Mat(h, w, CV_8UC4, frame.data[0], frame.linesize[0]).clone()};
  }
  std::lock_guard lock(mutex_);
  frames_.push_back(std::move(p));
}

std::vector<Planes> Capture::frames() const {
  std::lock_guard lock(mutex_);
  return frames_;
}

bool Capture::seen(std::uint64_t timestamp) const {
  std::lock_guard lock(mutex_);
  for (const Planes& p : frames_)
    if (p.timestamp == timestamp) return true;
  return false;
}

void Capture::clear() {
  std::lock_guard lock(mutex_);
  frames_.clear();
}

Obs& Obs::get() {
  static Obs obs;
  return obs;
}

Obs::Obs() {
  Display* display = XOpenDisplay(nullptr);
  if (display == nullptr) {
    ADD_FAILURE() << "no X display: run under xvfb-run -a";
    return;
  }
  obs_set_nix_platform(OBS_NIX_PLATFORM_X11_EGL);
  obs_set_nix_platform_display(display);
  if (!obs_startup("en-US", nullptr, nullptr)) {
    ADD_FAILURE() << "obs_startup failed";
    return;
  }
  obs_video_info v{};
  v.graphics_module = "libobs-opengl";
  v.fps_num = 30, v.fps_den = 1;
  v.base_width = v.output_width = kWidth;
  v.base_height = v.output_height = kHeight;
  v.output_format = VIDEO_FORMAT_BGRA;
  v.colorspace = VIDEO_CS_709;
  v.range = VIDEO_RANGE_FULL;
  v.scale_type = OBS_SCALE_POINT;
  v.gpu_conversion = true;
  if (obs_reset_video(&v) != OBS_VIDEO_SUCCESS) {
    ADD_FAILURE() << "obs_reset_video failed (Mesa llvmpipe: LIBGL_ALWAYS_SOFTWARE=1)";
    return;
  }
  register_test_types();
  obs_module_t* module = nullptr;
  const int opened = obs_open_module(&module, paths().module.c_str(), paths().data.c_str());
  if (opened != MODULE_SUCCESS || !obs_init_module(module)) {
    ADD_FAILURE() << "cannot load " << paths().module << " (obs_open_module: " << opened << ")";
    return;
  }
  obs_add_raw_video_callback(nullptr, on_output, this);
  ok_ = true;
}

void Obs::shutdown() {
  if (!ok_) return;
  obs_remove_raw_video_callback(on_output, this);
  obs_shutdown();
  ok_ = false;
}

Obs::Chain Obs::make_chain(obs_data_t* settings) {
  Chain c;
  c.source = obs_source_create("ifsfx_test_source", "camera", nullptr, nullptr);
  // The newest frame at every tick, whatever its timestamp: one filter call per frame shown.
  obs_source_set_async_unbuffered(c.source, true);
  c.filter = obs_source_create("ifsfx_fractal_filter", "fractal", settings, nullptr);
  c.probe = obs_source_create("ifsfx_test_probe", "probe", nullptr, nullptr);
  // Filters run in the order they were added: ifsfx's, then the probe's.
  if (c.filter) obs_source_filter_add(c.source, c.filter);
  obs_source_filter_add(c.source, c.probe);
  obs_set_output_source(0, c.source);
  return c;
}

void Obs::release(Chain& c) {
  obs_set_output_source(0, nullptr);
  for (obs_source_t* filter : {c.filter, c.probe}) {
    if (filter == nullptr) continue;
    obs_source_filter_remove(c.source, filter);
    obs_source_release(filter);
  }
  obs_source_release(c.source);
  c = {};
}

bool Obs::show(obs_source_t* source, const Planes& frame, std::int64_t index) {
  obs_source_frame f{};
  for (std::size_t i = 0; i < frame.planes.size(); ++i) {
    f.data[i] = frame.planes[i].data;
    f.linesize[i] = static_cast<std::uint32_t>(frame.planes[i].step[0]);
  }
  f.width = kWidth, f.height = kHeight;
  f.format = frame.format;
  f.timestamp = kOrigin + static_cast<std::uint64_t>(index) * 1'000'000'000 / 30;
  if (frame.format == VIDEO_FORMAT_NV12) {
    f.full_range = false;
    video_format_get_parameters(VIDEO_CS_709, VIDEO_RANGE_PARTIAL, f.color_matrix,
                                f.color_range_min, f.color_range_max);
  }
  obs_source_output_video(source, &f);
  // OBS's video thread renders the frame at its next 30 Hz tick (llvmpipe, software GL); a CI
  // machine running other tests beside this one can hold it back for seconds (2 s was too short).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (!capture_.seen(f.timestamp)) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

cv::Mat Obs::output() const {
  std::lock_guard lock(output_mutex_);
  return output_.clone();
}

void Obs::set_output(const cv::Mat& picture) {
  std::lock_guard lock(output_mutex_);
  picture.copyTo(output_);
}

cv::Mat test_frame(int k) {
  cv::Mat hsv(kHeight, kWidth, CV_8UC3);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      hsv.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<std::uint8_t>((x * 180 / kWidth + 20 * k) % 180),
                    static_cast<std::uint8_t>(120 + y * 135 / kHeight), 230);
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  for (int d = 0; d < 4; ++d)
    cv::circle(bgr, {40 + 70 * d + 9 * k, 60 + 40 * (d % 2) + 5 * k}, 22 + 4 * d,
               cv::Scalar(40 * d, 255 - 60 * d, 90 + 50 * d), cv::FILLED, cv::LINE_AA);
  return bgr;
}

Planes bgra_frame(const cv::Mat& bgr) {
  Planes p;
  p.planes.resize(1);
  cv::cvtColor(bgr, p.planes[0], cv::COLOR_BGR2BGRA);
  return p;
}

std::vector<cv::Mat> cli_frames(const std::vector<cv::Mat>& frames, const std::string& flags,
                                const std::string& name) {
  const fs::path dir = fs::path(paths().work) / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "in");
  fs::create_directories(dir / "out");
  for (std::size_t i = 0; i < frames.size(); ++i) {
    char file[32];
    std::snprintf(file, sizeof file, "f_%04zu.png", i);
    cv::imwrite((dir / "in" / file).string(), frames[i]);
  }
  const std::string command = paths().ifsfx + " filter " + (dir / "in/f_%04d.png").string() +
                              " -o " + (dir / "out/f_%04d.png").string() + " --fps 30 -q " + flags;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::vector<cv::Mat> out;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    char file[32];
    std::snprintf(file, sizeof file, "f_%04zu.png", i);
    out.push_back(cv::imread((dir / "out" / file).string(), cv::IMREAD_COLOR));
  }
  return out;
}

std::string cli_error(const std::string& flags) {
  const fs::path dir = fs::path(paths().work) / "cli_error";
  fs::create_directories(dir);
  cv::imwrite((dir / "f_0000.png").string(), test_frame(0));
  const std::string command = paths().ifsfx + " filter " + (dir / "f_%04d.png").string() + " -o " +
                              (dir / "out_%04d.png").string() + " -q " + flags + " 2> " +
                              (dir / "stderr.txt").string();
  EXPECT_NE(std::system(command.c_str()), 0) << command;
  std::string message = read_file(dir / "stderr.txt");
  if (message.rfind("ifsfx: ", 0) == 0) message.erase(0, 7);
  while (!message.empty() && message.back() == '\n') message.pop_back();
  return message;
}

}  // namespace ifsfx::obs_test
