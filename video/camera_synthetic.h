// SPDX-License-Identifier: Apache-2.0
// A synthetic live source: a moving test pattern "captured" in real time at a fixed rate, for
// benchmarking and testing the live loop without a camera. Frame k is captured at
// clock_origin() + k / fps whether or not anyone reads it; read() returns the newest captured
// frame (waiting for the next one if the newest was already returned) and counts the frames it
// skipped as dropped — a camera driver with few buffers behaves the same way.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "video/camera_source.h"

namespace ifsfx::video {

struct SyntheticCameraOptions {
  cv::Size size{1280, 720};
  double fps = 30;
  std::int64_t frame_count = 0;  // end of stream after this many frames captured; 0 = endless
  int patterns = 30;             // distinct frames, cycled (made once, up front)
  // Thrown from read() once this many frames have been returned, to exercise fault handling
  // (a camera unplugged mid-stream); 0 = never.
  std::int64_t fail_after = 0;
};

class SyntheticCamera final : public LiveSource {
 public:
  explicit SyntheticCamera(const SyntheticCameraOptions& options = {});

  std::optional<Frame> read() override;
  cv::Size size() const override { return options_.size; }
  double fps() const override { return options_.fps; }
  std::string name() const override { return "synthetic"; }
  std::chrono::steady_clock::time_point clock_origin() const override { return origin_; }
  std::int64_t dropped() const override { return dropped_; }

  // The image of frame k (what read() returns for it).
  const cv::Mat& pattern(std::int64_t k) const;

 private:
  SyntheticCameraOptions options_;
  std::vector<cv::Mat> patterns_;
  std::chrono::steady_clock::time_point origin_;
  std::int64_t next_ = 0;  // first frame not yet returned or skipped
  std::int64_t returned_ = 0;
  std::int64_t dropped_ = 0;
};

}  // namespace ifsfx::video
