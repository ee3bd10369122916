// SPDX-License-Identifier: Apache-2.0
#include "video/camera_synthetic.h"

#include <cmath>
#include <thread>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::video {

namespace {

using Clock = std::chrono::steady_clock;

// Frame k of n: diagonal colour bands drifting across the frame, plus a bright square whose place
// encodes k, so that consecutive frames differ everywhere.
cv::Mat make_pattern(cv::Size size, int k, int n) {
  cv::Mat image(size, CV_8UC3);
  const double phase = 2 * M_PI * k / n;
  for (int y = 0; y < size.height; ++y) {
    auto* row = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      const double t = 2 * M_PI * (x + y) / std::max(size.width, 64) * 3 + phase;
      row[x] = {static_cast<std::uint8_t>(127.5 + 127.5 * std::sin(t)),
                static_cast<std::uint8_t>(127.5 + 127.5 * std::sin(t + 2.1)),
                static_cast<std::uint8_t>(127.5 + 127.5 * std::sin(t + 4.2))};
    }
  }
  const int side = std::max(1, std::min(size.width, size.height) / 8);
  const int x0 = (size.width - side) * k / std::max(1, n - 1);
  cv::rectangle(image, cv::Rect(x0, size.height / 2 - side / 2, side, side), cv::Scalar::all(255),
                cv::FILLED);
  return image;
}

}  // namespace

SyntheticCamera::SyntheticCamera(const SyntheticCameraOptions& options) : options_(options) {
  if (options.fps <= 0 || options.patterns < 1 || options.size.width < 1 ||
      options.size.height < 1) {
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("synthetic camera: fps, patterns and size must be positive (got {} "
                    "fps, {} patterns, {}x{})",
                    options.fps, options.patterns, options.size.width, options.size.height));
  }
  for (int k = 0; k < options.patterns; ++k) {
    patterns_.push_back(make_pattern(options.size, k, options.patterns));
  }
  origin_ = Clock::now();
}

const cv::Mat& SyntheticCamera::pattern(std::int64_t k) const {
  return patterns_[static_cast<std::size_t>(k % options_.patterns)];
}

std::optional<Frame> SyntheticCamera::read() {
  if (options_.fail_after > 0 && returned_ >= options_.fail_after) {
    throw Error(ErrorKind::device, "synthetic: device vanished (simulated)");
  }
  const double interval = 1 / options_.fps;
  const auto capture_time = [&](std::int64_t k) {
    return origin_ +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(k * interval));
  };
  // The newest frame captured by now; if it was already returned, wait for the next one.
  auto newest = static_cast<std::int64_t>(
      std::floor(std::chrono::duration<double>(Clock::now() - origin_).count() / interval));
  if (newest < next_) {
    newest = next_;
    std::this_thread::sleep_until(capture_time(newest));
  }
  if (options_.frame_count > 0 && newest >= options_.frame_count) {
    dropped_ += std::max<std::int64_t>(0, options_.frame_count - next_);
    next_ = options_.frame_count;
    return std::nullopt;
  }
  dropped_ += newest - next_;
  next_ = newest + 1;
  ++returned_;
  Frame frame;
  frame.image = pattern(newest);
  frame.index = newest;
  frame.timestamp = newest * interval;
  return frame;
}

}  // namespace ifsfx::video
