// SPDX-License-Identifier: Apache-2.0
// A V4L2 camera as a frame source, on the kernel API: VIDIOC_QUERYCAP, VIDIOC_ENUM_FMT,
// VIDIOC_S_FMT, VIDIOC_S_PARM, VIDIOC_REQBUFS, mmap streaming with VIDIOC_QBUF/VIDIOC_DQBUF and
// VIDIOC_STREAMON/VIDIOC_STREAMOFF. Few buffers and newest-frame-wins for low latency: read()
// drains every filled buffer, keeps the newest and hands the rest straight back to the driver.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "video/camera_source.h"
#include "video/v4l2_convert.h"

namespace ifsfx::video {

struct V4l2CaptureOptions {
  cv::Size size{640, 480};  // requested; the driver grants the nearest it has (see size())
  double fps = 30;          // requested; 0 leaves the device's rate (see fps())
  // Formats tried in this order; the first the device offers at the requested size and rate
  // wins, else the first it offers at all. Empty: every format we convert, uncompressed first.
  std::vector<PixelFormat> formats;
  int buffers = 3;        // driver buffers: more smooths jitter, fewer keeps latency down
  int timeout_ms = 3000;  // no frame for this long: Error{device} "stalled", never a hang
  int input = -1;         // VIDIOC_S_INPUT index; -1 leaves the current input
};

class V4l2Capture final : public LiveSource {
 public:
  // Opens, negotiates and maps the buffers; streaming starts with the first read(). Throws
  // Error{not_found} for a missing node, Error{unsupported} for a node that is not a streaming
  // capture device or offers none of the requested formats, Error{device} for a busy one, all
  // naming the device.
  //   V4l2Capture camera("/dev/video0", {.size = {1280, 720}, .fps = 30});
  explicit V4l2Capture(const std::string& device, const V4l2CaptureOptions& options = {});
  ~V4l2Capture() override;
  V4l2Capture(const V4l2Capture&) = delete;
  V4l2Capture& operator=(const V4l2Capture&) = delete;

  // The newest frame (BGR). Waits for one with poll(); throws Error{device} when the camera
  // vanishes (ENODEV) or stalls past the timeout. Frame::index is the driver's sequence number
  // counted from the first frame, so gaps are drops; Frame::timestamp is the capture time (the
  // driver's monotonic timestamp, else the moment of dequeue) after clock_origin().
  std::optional<Frame> read() override;

  cv::Size size() const override;  // granted size
  double fps() const override;     // granted rate (0 when the driver does not say)
  std::string name() const override;
  std::chrono::steady_clock::time_point clock_origin() const override;
  std::int64_t dropped() const override;

  PixelFormat format() const;  // granted pixel format
  std::string card() const;    // the driver's name for the device, e.g. "vivid"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ifsfx::video
