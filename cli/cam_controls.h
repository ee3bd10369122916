// SPDX-License-Identifier: Apache-2.0
// What the keys of the `ifsfx cam` window do to the live session: n/p step through the shipped
// presets, a turns the drift animation on and off, s writes a snapshot, r starts and stops a
// recording. Each action is reported: on stderr and, for a few seconds, in the window's readout.
#pragma once

#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "cli/cam_recording.h"
#include "cli/live_filter.h"
#include "run/fractal_filter_options.h"

namespace ifsfx::app {

// The last action, on stderr unless quiet, and as the window's second readout line while fresh.
class Notices {
 public:
  explicit Notices(bool quiet) : quiet_(quiet) {}
  void operator()(const std::string& text);
  // The latest notice for three seconds after it was given, else "".
  std::string current() const;

 private:
  bool quiet_;
  std::string text_;
  std::chrono::steady_clock::time_point until_;
};

struct CamControlsSetup {
  const FractalFilterArgs* fractal = nullptr;  // outlives the controls
  int fade_frames = 12;
  cv::Size size;         // the camera's granted frame size
  double fps = 25;       // the camera's frame rate
  std::string snapshot;  // file pattern of the snapshots (one %d or %0Nd)
  bool animate = false;  // the drift animation on at the start
};

class CamControls {
 public:
  // Computes the starting preset's map (fractal->preset): throws what LiveFilter throws.
  CamControls(const CamControlsSetup& setup, CamRecording& recording, Notices& notice);
  CamControls(const CamControls&) = delete;
  CamControls& operator=(const CamControls&) = delete;

  LiveFilter& filter() { return *filter_; }

  // Acts on one key: 'n', 'p', 'a', 's' (`shown` is the picture snapshotted), 'r'; others are
  // ignored. A snapshot or recording that fails is reported and the session goes on.
  void key(int key, const cv::Mat& shown);
  // Between frames: hands over to a preset whose map has been computed meanwhile.
  void poll();
  // Maps built by every drift animation so far.
  std::int64_t drift_maps() const { return drift_maps_ + filter_->maps_built(); }

 private:
  void step_preset(bool forward);
  void start_switch(std::size_t index);
  void snapshot(const cv::Mat& image);
  void toggle_recording();

  CamControlsSetup setup_;
  CamRecording& recording_;
  Notices& notice_;
  std::unique_ptr<LiveFilter> filter_;
  bool animate_;
  std::int64_t drift_maps_ = 0;  // built by animations that have ended

  // n/p: the next preset's map is computed on a worker while the current filter stays live (a map
  // takes several frame intervals); keys pressed meanwhile pick the preset to go to after it.
  std::vector<std::string> presets_;
  std::optional<std::size_t> index_;  // of the preset shown, when it is a shipped one
  struct Switch {
    std::size_t index;
    std::future<std::unique_ptr<LiveFilter>> filter;
  };
  std::optional<Switch> pending_;  // destroyed first: waits for a map under way
  std::optional<std::size_t> wanted_;
};

}  // namespace ifsfx::app
