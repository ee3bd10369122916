// SPDX-License-Identifier: Apache-2.0
// Video in `ifsfx studio` (docs/studio.md): a movie of the folder (or --source) scrubbed frame by
// frame and a camera (--camera), each frame shown through the fractal filter of the preset being
// edited — the one FractalEngine of `ifsfx filter` and `ifsfx cam` (docs/design.md §10), with its
// drift animation.
//
// A preview request: the preset of /api/render plus
//   {"filter": true, "animate": "none" | "drift", "drift_amount": 0.05, "drift_speed": 0.2,
//    "mix": 0, "background": "black", "exact": true, "view": "x0,y0,x1,y1", "seed": 1,
//    "keyframe_interval": 12, "width": 640}
// and for a movie {"movie": NAME, "frame": N}.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "engine/fractal_engine.h"
#include "studio/context.h"
#include "video/file_source.h"
#include "video/v4l2_capture.h"

namespace ifsfx::app {

// Frames of the folder's movies, per tab: the tab's decoder is kept, so that playing (frame N,
// then N + 1) decodes one frame each; any other frame is found by FileSource::seek.
class MovieFrames {
 public:
  // {"movie", "frames" (counted exactly), "fps", "width", "height"}. Throws what FileSource
  // throws, naming the file.
  static nlohmann::json info(const std::filesystem::path& movie, const std::string& name);

  // Frame `index` (from 0) of `movie`, 8-bit BGR, and the movie's frame rate. Throws
  // Error{invalid_argument} for a frame beyond the end.
  cv::Mat frame(const std::string& client, const std::filesystem::path& movie, std::int64_t index,
                double& fps);

 private:
  struct Cursor {
    std::filesystem::path movie;
    std::int64_t next = 0;
    std::unique_ptr<video::FileSource> source;
    std::uint64_t used = 0;
  };
  static constexpr std::size_t kMaxTabs = 8;
  std::mutex mutex_;
  std::map<std::string, std::unique_ptr<Cursor>> cursors_;  // by tab; out while in use
  std::uint64_t clock_ = 0;
};

// The fractal filter for previews, per tab and channel (movie, camera): the engine of the
// settings asked for last is kept, so frames of one look cost a remap (and the drift's
// keyframes, built ahead); other settings replace it and stop its maps in flight (409).
class FilterPreviews {
 public:
  // `frame` (BGR) through the filter of `body` at frame `index` of a stream of `fps`, or, with
  // `seconds` ≥ 0, at that time (a camera); scaled to body["width"] (default 640) at most. Without
  // "filter" (false) the frame scaled. Returns JPEG bytes. Throws Error{parse} for a bad field
  // and what the engine throws (Error{interrupted} when superseded).
  std::string jpeg(const std::string& channel, const nlohmann::json& body, const cv::Mat& frame,
                   std::int64_t index, double seconds, double fps);
  void stop_all();

 private:
  struct Entry {
    std::string key;
    std::atomic<bool> stop{false};
    std::mutex use;  // an engine serves one frame at a time
    std::unique_ptr<engine::FractalEngine> engine;
    std::uint64_t used = 0;
  };
  static constexpr std::size_t kMaxEntries = 8;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<Entry>> entries_;  // by channel and tab
  std::uint64_t clock_ = 0;
  bool stopping_ = false;
};

// The camera of --camera, opened at the first frame asked for and shared by every tab. A camera
// that fails (unplugged, busy, no such device) is closed and its error becomes RequestError 503
// with the device's message; the next frame asked for opens it again.
class CameraFeed {
 public:
  explicit CameraFeed(std::string device) : device_(std::move(device)) {}
  const std::string& device() const { return device_; }
  // The newest frame (BGR) and its capture time in seconds since the camera was opened.
  cv::Mat frame(double& seconds);
  // Closes the device (the page left the camera view); the next frame opens it again.
  void close();

 private:
  std::string device_;
  std::mutex mutex_;
  std::unique_ptr<video::V4l2Capture> camera_;
};

}  // namespace ifsfx::app
