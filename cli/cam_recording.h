// SPDX-License-Identifier: Apache-2.0
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
  // `first` is taken as given when `exact` (the --record path, replaced like any output when the
  // recording ends); otherwise, and for every later file, the first free name FIRST-2, FIRST-3,
  // ... is used. Every file goes through the output policy `output` (ifs/output_file.h).
  CamRecording(std::filesystem::path first, bool exact, std::string codec, cv::Size size,
               double fps, OutputOptions output = {});

  bool recording() const { return file_ != nullptr; }
  // The file being (or last) recorded, and its frames so far.
  const std::filesystem::path& path() const { return path_; }
  std::int64_t frames() const { return file_ ? file_->frames_written() : frames_; }
  // Where the last recording was kept when the session ended by a fault (abandon()), else empty.
  const std::filesystem::path& partial() const { return partial_; }

  // Starts a new file (Error{io} when it cannot be created; nothing changes then).
  void start();
  // Finalises the file being recorded, if any.
  void stop();

  void write(const video::Frame& frame) override;
  void close() override { stop(); }
  // The recording did not end normally: its frames are kept as a partial movie (see partial()).
  std::filesystem::path abandon() noexcept override;
  std::string name() const override { return path_.string(); }

 private:
  std::filesystem::path first_, path_, partial_;
  bool exact_ = false;
  std::string codec_;
  cv::Size size_;
  double fps_;
  int started_ = 0;
  std::int64_t frames_ = 0;
  OutputOptions output_;
  std::unique_ptr<video::FileSink> file_;
};

}  // namespace ifsfx::app
