// SPDX-License-Identifier: Apache-2.0
#include "cli/cam_recording.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace ifsfx::app {

CamRecording::CamRecording(std::filesystem::path first, bool exact, std::string codec,
                           cv::Size size, double fps, OutputOptions output)
    : first_(std::move(first)),
      exact_(exact),
      codec_(std::move(codec)),
      size_(size),
      fps_(fps),
      output_(std::move(output)) {}

void CamRecording::start() {
  if (file_) return;
  std::filesystem::path p = first_;
  if (started_ > 0 || !exact_) {
    for (int n = 2; std::filesystem::exists(p); ++n) {
      p = first_.parent_path() /
          fmt::format("{}-{}{}", first_.stem().string(), n, first_.extension().string());
    }
  }
  video::FileSinkOptions o;
  o.codec = codec_;
  o.size = size_;
  o.output = output_;
  // A camera's rate is usually whole (30) or NTSC-like (29.97): keep it exact either way.
  o.frame_rate = video::rate_from_fps(fps_);
  file_ = std::make_unique<video::FileSink>(p, o);
  path_ = p;
  frames_ = 0;
  ++started_;
}

void CamRecording::stop() {
  if (!file_) return;
  // Counted after closing: a constant-rate file writes its held-back last frame then.
  auto file = std::move(file_);
  file->close();
  frames_ = file->frames_written();
}

std::filesystem::path CamRecording::abandon() noexcept {
  if (!file_) return {};
  partial_ = file_->abandon();
  frames_ = file_->frames_written();  // after abandon(): it writes the held-back last frame
  file_.reset();
  return partial_;
}

void CamRecording::write(const video::Frame& frame) {
  if (file_) file_->write(frame);
}

}  // namespace ifsfx::app
