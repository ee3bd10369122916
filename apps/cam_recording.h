// A recording that the live loop of `ifsfx cam` can start and stop while it runs (the window's r
// key), each start a new movie file through the file sink of `ifsfx filter`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "video/file_sink.h"
#include "video/frame_io.h"

namespace ifsfx::app {

// A sink that forwards frames to a movie file while recording is on, so the live loop can hold
// one fixed list of sinks.
class CamRecording final : public video::FrameSink {
 public:
  // `first` is taken as given when `exact` (the --record path, overwritten like any output);
  // otherwise, and for every later file, the first free name FIRST-2, FIRST-3, ... is used.
  CamRecording(std::filesystem::path first, bool exact, std::string codec, cv::Size size,
               double fps);

  bool recording() const { return file_ != nullptr; }
  // The file being (or last) recorded, and its frames so far.
  const std::filesystem::path& path() const { return path_; }
  std::int64_t frames() const { return file_ ? file_->frames_written() : frames_; }

  // Starts a new file (Error{io} when it cannot be created; nothing changes then).
  void start();
  // Finalises the file being recorded, if any.
  void stop();

  void write(const video::Frame& frame) override;
  void close() override { stop(); }
  std::string name() const override { return path_.string(); }

 private:
  std::filesystem::path first_, path_;
  bool exact_ = false;
  std::string codec_;
  cv::Size size_;
  double fps_;
  int started_ = 0;
  std::int64_t frames_ = 0;
  std::unique_ptr<video::FileSink> file_;
};

}  // namespace ifsfx::app
