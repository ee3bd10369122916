// SPDX-License-Identifier: Apache-2.0
// A headless OBS for the filter's tests: libobs started on the X display of xvfb-run (Mesa's
// llvmpipe), BGRA video at 30 fps, the built ifsfx-obs module loaded through obs_open_module,
// a synthetic async source of our own that outputs known frames (as a webcam does, through
// obs_source_output_video), and a probe filter placed after ifsfx's that copies every frame it
// sees — the filter's bytes exactly, before OBS draws them.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <obs.h>
#include <opencv2/core.hpp>

namespace ifsfx::obs_test {

struct Paths {
  std::string module;  // ifsfx-obs.so
  std::string data;    // its data folder (locale/en-US.ini)
  std::string ifsfx;   // the command, for the pictures to compare with
  std::string work;    // a folder for this test's files
};
Paths& paths();

// A frame in OBS's layout: BGRA (one CV_8UC4 plane) or NV12 (CV_8UC1 luma, CV_8UC2 chroma).
struct Planes {
  video_format format = VIDEO_FORMAT_BGRA;
  std::uint64_t timestamp = 0;
  std::vector<cv::Mat> planes;
};

// What the probe filter saw, in order.
class Capture {
 public:
  void add(const obs_source_frame& frame);
  std::vector<Planes> frames() const;
  bool seen(std::uint64_t timestamp) const;
  void clear();

 private:
  mutable std::mutex mutex_;
  std::vector<Planes> frames_;
};

// libobs, started once per test program (obs_startup ... obs_shutdown).
class Obs {
 public:
  static Obs& get();  // starts it on first use; ADD_FAILURE and nullptr-safe calls when it cannot
  bool ok() const { return ok_; }
  // obs_shutdown, once every test is done (the module's filters are gone by then).
  void shutdown();
  Capture& capture() { return capture_; }

  // A synthetic source on output channel 0, with the ifsfx filter (of `settings`, taken over)
  // and then the probe.
  struct Chain {
    obs_source_t* source = nullptr;
    obs_source_t* filter = nullptr;
    obs_source_t* probe = nullptr;
  };
  Chain make_chain(obs_data_t* settings);
  void release(Chain& chain);

  // Outputs `frame` with timestamp `index` frames of 30 fps after an arbitrary origin and waits
  // (up to 15 s) for the probe to see it; false if it did not.
  bool show(obs_source_t* source, const Planes& frame, std::int64_t index);

  // The newest picture of OBS's BGRA output (obs_add_raw_video_callback).
  cv::Mat output() const;
  void set_output(const cv::Mat& picture);  // the raw video callback's

 private:
  Obs();
  bool ok_ = false;
  Capture capture_;
  mutable std::mutex output_mutex_;
  cv::Mat output_;
};

inline constexpr int kWidth = 320, kHeight = 240;
inline constexpr std::uint64_t kOrigin = 1'000'000'000;  // ns of frame 0

// Synthetic test frames (CV_8UC3 BGR): a colour wheel with moving discs, different for each k.
cv::Mat test_frame(int k);
// BGR → BGRA planes, opaque.
Planes bgra_frame(const cv::Mat& bgr);

// Runs `ifsfx filter` on `frames` (written as a PNG sequence) with `flags`; its output frames.
std::vector<cv::Mat> cli_frames(const std::vector<cv::Mat>& frames, const std::string& flags,
                                const std::string& name);
// The one-line message `ifsfx filter` gives for `flags` (without "ifsfx: ").
std::string cli_error(const std::string& flags);

}  // namespace ifsfx::obs_test
