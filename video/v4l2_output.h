// SPDX-License-Identifier: Apache-2.0
// A V4L2 video output device as a frame sink: the kaleidoscope as a webcam for any app, through a
// v4l2loopback node (`--output /dev/video10`). Frames go out as YUYV or YUV420, the formats
// browsers and video-call apps accept: with write() where the device takes it (v4l2loopback),
// else by mmap streaming (VIDIOC_REQBUFS/QBUF/DQBUF on the OUTPUT queue).
#pragma once

#include <memory>
#include <string>

#include "video/frame_io.h"
#include "video/v4l2_convert.h"

namespace ifsfx::video {

struct V4l2OutputOptions {
  PixelFormat format = PixelFormat::yuyv;  // yuyv or yuv420
  double fps = 30;                         // announced to readers (VIDIOC_S_PARM), if taken
  int timeout_ms = 3000;                   // mmap streaming: no free buffer for this long fails
};

class V4l2Output final : public FrameSink {
 public:
  // Opens `device` and sets its OUTPUT format to `size` in options.format. Throws Error{not_found}
  // for a missing node, Error{unsupported} for a node without video output or that will not take
  // the format at this size, Error{device} when busy, naming the device.
  //   V4l2Output webcam("/dev/video10", {1280, 720});
  V4l2Output(const std::string& device, cv::Size size, const V4l2OutputOptions& options = {});
  ~V4l2Output() override;
  V4l2Output(const V4l2Output&) = delete;
  V4l2Output& operator=(const V4l2Output&) = delete;

  // Sends one BGR frame of the configured size. Throws Error{invalid_argument} for another size
  // and Error{device} when the device goes away (ENODEV) or refuses the frame.
  void write(const Frame& frame) override;
  void close() override;
  std::string name() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ifsfx::video
