// SPDX-License-Identifier: Apache-2.0
// Synthetic frames and in-memory sources and sinks shared by the video tests.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/steal_map.h"
#include "video/frame_io.h"

namespace ifsfx::video::testing {

// A frame that differs from every other index: smooth gradients, a moving square and a little
// texture, so that both remaps and codecs see something real.
inline cv::Mat test_frame(cv::Size size, std::int64_t index) {
  cv::Mat image(size, CV_8UC3);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      image.at<cv::Vec3b>(r, c) =
          cv::Vec3b(static_cast<std::uint8_t>((c * 255) / std::max(1, size.width - 1)),
                    static_cast<std::uint8_t>((r * 255) / std::max(1, size.height - 1)),
                    static_cast<std::uint8_t>((index * 37 + (r / 4 + c / 4) * 8) & 255));
  const int x = static_cast<int>((index * 5) % std::max(1, size.width - 8));
  cv::rectangle(image, {x, size.height / 4, 8, 8}, cv::Scalar(255, 255, 255), cv::FILLED);
  return image;
}

// The identity steal map: every output pixel takes the source at its own centre (what the
// 4-map tiling as both F and G gives, docs/design.md §3's oracle).
inline StealMap identity_map(cv::Size size) {
  StealMap map;
  map.source_uv.create(size, CV_32FC2);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      map.source_uv.at<cv::Vec2f>(r, c) = {(c + 0.5f) / size.width, (r + 0.5f) / size.height};
  map.coverage = cv::Mat(size, CV_8UC1, cv::Scalar(255));
  return map;
}

inline double psnr(const cv::Mat& a, const cv::Mat& b) {
  return cv::PSNR(a, b);
}

class MemorySource final : public FrameSource {
 public:
  MemorySource(cv::Size size, std::int64_t count, double fps = 25)
      : size_(size), count_(count), fps_(fps) {}
  std::optional<Frame> read() override {
    if (next_ >= count_) return std::nullopt;
    Frame f{test_frame(size_, next_), next_, static_cast<double>(next_) / fps_};
    ++next_;
    return f;
  }
  cv::Size size() const override { return size_; }
  double fps() const override { return fps_; }
  std::int64_t frame_count() const override { return count_; }
  std::string name() const override { return "memory"; }
  std::int64_t reads() const { return next_; }

 private:
  cv::Size size_;
  std::int64_t count_;
  double fps_;
  std::int64_t next_ = 0;
};

// Counts how its output ended: closed (complete) or abandoned (failed or stopped); an abandoned
// output says it kept its frames in `partial` when that is set.
class MemorySink final : public FrameSink {
 public:
  void write(const Frame& frame) override { frames.push_back(frame); }
  void close() override { ++closes; }
  std::filesystem::path abandon() noexcept override {
    ++abandons;
    return partial;
  }
  std::string name() const override { return "memory"; }
  std::vector<Frame> frames;
  int closes = 0;
  int abandons = 0;
  std::filesystem::path partial;
};

// A fresh empty folder under the system's temporary folder, named for the test.
inline std::filesystem::path temp_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("ifsfx-video-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace ifsfx::video::testing
