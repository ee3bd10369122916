// SPDX-License-Identifier: Apache-2.0
#include "video/v4l2_output.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <vector>

#include <fmt/format.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <unistd.h>

#include "ifs/error.h"
#include "video/v4l2_device.h"

namespace ifsfx::video {

namespace {

using detail::MappedBuffer;
using detail::throw_errno;
using detail::xioctl;

// Waits until the node can take data; throws on timeout or a device error.
void wait_writable(int fd, const std::string& path, int timeout_ms) {
  for (;;) {
    pollfd p{fd, POLLOUT, 0};
    const int r = ::poll(&p, 1, timeout_ms);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw_errno(path, "poll", errno);
    if (r == 0) {
      throw Error(ErrorKind::device,
                  fmt::format("{}: output device took no frame for {} ms", path, timeout_ms));
    }
    return;
  }
}

}  // namespace

struct V4l2Output::Impl {
  detail::V4l2Fd fd;
  std::string path;
  cv::Size size;
  PixelFormat format = PixelFormat::yuyv;
  int timeout_ms = 3000;
  bool use_write = true;
  std::vector<MappedBuffer> buffers;
  std::size_t queued_once = 0;  // mmap: buffers filled and queued before the first DQBUF
  bool streaming = false;
  std::vector<std::uint8_t> scratch;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { stop(); }

  void stop() noexcept {
    if (streaming) {
      int type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
      xioctl(fd.get(), VIDIOC_STREAMOFF, &type);
      streaming = false;
    }
    detail::unmap_buffers(buffers);
    fd.reset();
  }

  void send_write() {
    std::size_t done = 0;
    while (done < scratch.size()) {
      const ssize_t n = ::write(fd.get(), scratch.data() + done, scratch.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        if (errno == EAGAIN) {
          wait_writable(fd.get(), path, timeout_ms);
          continue;
        }
        throw_errno(path, "write", errno);
      }
      if (n == 0) throw Error(ErrorKind::device, fmt::format("{}: write took no bytes", path));
      done += static_cast<std::size_t>(n);
    }
  }

  void send_mmap() {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    b.memory = V4L2_MEMORY_MMAP;
    if (queued_once < buffers.size()) {
      b.index = static_cast<std::uint32_t>(queued_once++);
    } else {
      wait_writable(fd.get(), path, timeout_ms);
      if (xioctl(fd.get(), VIDIOC_DQBUF, &b) != 0) throw_errno(path, "VIDIOC_DQBUF", errno);
    }
    MappedBuffer& m = buffers.at(b.index);
    if (m.length < scratch.size()) {
      throw Error(ErrorKind::device, fmt::format("{}: output buffer of {} bytes, frame needs {}",
                                                 path, m.length, scratch.size()));
    }
    std::memcpy(m.start, scratch.data(), scratch.size());
    b.bytesused = static_cast<std::uint32_t>(scratch.size());
    b.field = V4L2_FIELD_NONE;
    if (xioctl(fd.get(), VIDIOC_QBUF, &b) != 0) throw_errno(path, "VIDIOC_QBUF", errno);
    // The queue starts once every buffer holds a frame, so no stale buffer is ever shown.
    if (!streaming && queued_once == buffers.size()) {
      int type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
      if (xioctl(fd.get(), VIDIOC_STREAMON, &type) != 0)
        throw_errno(path, "VIDIOC_STREAMON", errno);
      streaming = true;
    }
  }
};

V4l2Output::V4l2Output(const std::string& device, cv::Size size, const V4l2OutputOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = device;
  m.size = size;
  m.format = options.format;
  m.timeout_ms = options.timeout_ms;
  if (options.format != PixelFormat::yuyv && options.format != PixelFormat::yuv420) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: output format must be yuyv or yuv420 (got {})", device,
                            fourcc_name(fourcc(options.format))));
  }
  if (size.width <= 0 || size.height <= 0 ||
      (options.format == PixelFormat::yuv420 && (size.width % 2 != 0 || size.height % 2 != 0))) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: output size {}x{} not possible in {}", device, size.width,
                            size.height, fourcc_name(fourcc(options.format))));
  }
  const V4l2DeviceInfo info = query_v4l2_device(device);
  if (!info.output) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: not a video output device ({}, {}); a virtual webcam needs "
                            "v4l2loopback",
                            device, info.driver, info.card));
  }
  m.use_write = info.read_write;
  if (!m.use_write && !info.streaming) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: output device takes neither write() nor streaming", device));
  }
  m.fd = detail::open_v4l2(device);
  const int fd = m.fd.get();

  v4l2_format fmt{};
  fmt.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
  fmt.fmt.pix.width = static_cast<std::uint32_t>(size.width);
  fmt.fmt.pix.height = static_cast<std::uint32_t>(size.height);
  fmt.fmt.pix.pixelformat = fourcc(options.format);
  fmt.fmt.pix.field = V4L2_FIELD_NONE;
  const bool yuyv = options.format == PixelFormat::yuyv;
  fmt.fmt.pix.bytesperline = static_cast<std::uint32_t>(size.width * (yuyv ? 2 : 1));
  fmt.fmt.pix.sizeimage = static_cast<std::uint32_t>(yuyv ? size.width * size.height * 2
                                                          : size.width * size.height * 3 / 2);
  fmt.fmt.pix.colorspace = V4L2_COLORSPACE_SMPTE170M;  // BT.601, as from_bgr writes
  const std::uint32_t want_bytes = fmt.fmt.pix.sizeimage;
  if (xioctl(fd, VIDIOC_S_FMT, &fmt) != 0) {
    if (errno == EINVAL || errno == EBUSY) {
      const bool busy = errno == EBUSY;
      throw Error(
          busy ? ErrorKind::device : ErrorKind::unsupported,
          fmt::format("{}: output format {} {}x{} {} (VIDIOC_S_FMT: {})", device,
                      fourcc_name(fourcc(options.format)), size.width, size.height,
                      busy ? "refused: device busy" : "not supported", busy ? "EBUSY" : "EINVAL"));
    }
    throw_errno(device, "VIDIOC_S_FMT", errno);
  }
  if (fmt.fmt.pix.pixelformat != fourcc(options.format) ||
      fmt.fmt.pix.width != static_cast<std::uint32_t>(size.width) ||
      fmt.fmt.pix.height != static_cast<std::uint32_t>(size.height) ||
      fmt.fmt.pix.sizeimage < want_bytes) {
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: output format {} {}x{} not supported (device offers {} {}x{})", device,
                    fourcc_name(fourcc(options.format)), size.width, size.height,
                    fourcc_name(fmt.fmt.pix.pixelformat), fmt.fmt.pix.width, fmt.fmt.pix.height));
  }
  if (options.fps > 0) {
    // Readers of a loopback device see this rate; devices that do not take it keep their own.
    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    parm.parm.output.timeperframe.numerator = 1000;
    parm.parm.output.timeperframe.denominator =
        static_cast<std::uint32_t>(std::lround(options.fps * 1000));
    xioctl(fd, VIDIOC_S_PARM, &parm);  // optional by the V4L2 spec: failure changes nothing
  }
  if (!m.use_write) {
    detail::map_buffers(fd, device, V4L2_BUF_TYPE_VIDEO_OUTPUT, 3, m.buffers);
  }
}

V4l2Output::~V4l2Output() = default;

void V4l2Output::write(const Frame& frame) {
  Impl& m = *impl_;
  if (m.fd.get() < 0) {
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: write after close", m.path));
  }
  if (frame.image.size() != m.size) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame is {}x{}, the output was set up for {}x{}", m.path,
                            frame.image.cols, frame.image.rows, m.size.width, m.size.height));
  }
  from_bgr(frame.image, m.format, m.scratch);
  if (m.use_write) {
    m.send_write();
  } else {
    m.send_mmap();
  }
}

void V4l2Output::close() {
  impl_->stop();
}

std::string V4l2Output::name() const {
  return impl_->path;
}

}  // namespace ifsfx::video
