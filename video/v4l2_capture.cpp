// SPDX-License-Identifier: Apache-2.0
#include "video/v4l2_capture.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include <fmt/format.h>
#include <linux/videodev2.h>
#include <poll.h>

#include "ifs/error.h"
#include "video/v4l2_device.h"

namespace ifsfx::video {

namespace {

using detail::MappedBuffer;
using detail::throw_errno;
using detail::xioctl;
using Clock = std::chrono::steady_clock;

// Uncompressed first: no decode cost, and no JPEG artefacts in the colour source.
const std::vector<PixelFormat> kDefaultFormats = {
    PixelFormat::yuyv,  PixelFormat::nv12,  PixelFormat::yuv420, PixelFormat::uyvy,
    PixelFormat::bgr24, PixelFormat::rgb24, PixelFormat::mjpeg};

// Consecutive undecodable frames tolerated before the stream counts as broken.
constexpr int kMaxBadFrames = 30;

// Whether `format` offers exactly `size` at `fps` or faster, per the device's enumeration. A
// device that enumerates no sizes (many do not) counts as offering everything.
bool offers(const V4l2Format& format, cv::Size size, double fps) {
  if (format.sizes.empty()) return true;
  if (format.stepwise_sizes) {
    const cv::Size lo = format.sizes.front().size, hi = format.sizes.back().size;
    return size.width >= lo.width && size.height >= lo.height && size.width <= hi.width &&
           size.height <= hi.height;
  }
  for (const V4l2FrameSize& s : format.sizes) {
    if (s.size != size) continue;
    if (fps <= 0 || s.fps.empty()) return true;
    if (s.stepwise_rates) return fps <= s.fps.front() + 0.5;
    return std::any_of(s.fps.begin(), s.fps.end(), [&](double r) { return r >= fps - 0.5; });
  }
  return false;
}

std::string offered_list(const std::vector<V4l2Format>& formats) {
  std::string list;
  for (const V4l2Format& f : formats) list += (list.empty() ? "" : ", ") + fourcc_name(f.fourcc);
  return list.empty() ? "none" : list;
}

// A device this class can capture from: a capture device with mmap streaming.
void check_capture_device(const std::string& device, const V4l2DeviceInfo& info) {
  if (!info.capture) {
    throw Error(ErrorKind::unsupported, fmt::format("{}: not a video capture device ({}, {})",
                                                    device, info.driver, info.card));
  }
  if (!info.streaming) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: device does not support mmap streaming ({})", device, info.card));
  }
}

// The format: the first preferred one offered at the requested size and rate, else the first
// preferred one offered at all.
const V4l2Format& choose_format(const std::string& device, const V4l2DeviceInfo& info,
                                const V4l2CaptureOptions& options) {
  const std::vector<PixelFormat>& wanted =
      options.formats.empty() ? kDefaultFormats : options.formats;
  for (int pass = 0; pass < 2; ++pass) {
    for (PixelFormat p : wanted) {
      const auto it = std::find_if(
          info.capture_formats.begin(), info.capture_formats.end(),
          [&](const V4l2Format& f) { return pixel_format_from_fourcc(f.fourcc) == p; });
      if (it == info.capture_formats.end()) continue;
      if (pass == 1 || offers(*it, options.size, options.fps)) return *it;
    }
  }
  std::string asked;
  for (PixelFormat p : wanted) asked += (asked.empty() ? "" : ", ") + fourcc_name(fourcc(p));
  throw Error(ErrorKind::unsupported,
              fmt::format("{}: pixel format not supported: asked for {} (device offers {})", device,
                          asked, offered_list(info.capture_formats)));
}

// Sets the format at `size` (VIDIOC_S_FMT); returns the layout the driver granted, which must be
// one we convert, progressive.
FrameLayout set_format(int fd, const std::string& device, const V4l2Format& chosen, cv::Size size) {
  v4l2_format fmt{};
  fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  fmt.fmt.pix.width = static_cast<std::uint32_t>(size.width);
  fmt.fmt.pix.height = static_cast<std::uint32_t>(size.height);
  fmt.fmt.pix.pixelformat = chosen.fourcc;
  fmt.fmt.pix.field = V4L2_FIELD_NONE;
  if (xioctl(fd, VIDIOC_S_FMT, &fmt) != 0) {
    if (errno == EINVAL) {
      throw Error(ErrorKind::unsupported,
                  fmt::format("{}: format {} {}x{} not supported (VIDIOC_S_FMT: EINVAL)", device,
                              fourcc_name(chosen.fourcc), size.width, size.height));
    }
    throw_errno(device, "VIDIOC_S_FMT", errno);
  }
  const auto granted = pixel_format_from_fourcc(fmt.fmt.pix.pixelformat);
  if (!granted) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: driver switched to pixel format {}, which we cannot convert",
                            device, fourcc_name(fmt.fmt.pix.pixelformat)));
  }
  if (fmt.fmt.pix.field != V4L2_FIELD_NONE && fmt.fmt.pix.field != V4L2_FIELD_ANY) {
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: interlaced video not supported (field order {})", device,
                            fmt.fmt.pix.field));
  }
  return {*granted,
          {static_cast<int>(fmt.fmt.pix.width), static_cast<int>(fmt.fmt.pix.height)},
          *granted == PixelFormat::mjpeg ? 0 : fmt.fmt.pix.bytesperline};
}

// The frame rate: asked for with S_PARM where the driver takes it, then read back; 0 when the
// driver does not say.
double set_frame_rate(int fd, const std::string& device, double fps) {
  v4l2_streamparm parm{};
  parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(fd, VIDIOC_G_PARM, &parm) != 0) return 0;
  if (fps > 0 && (parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME) != 0) {
    parm.parm.capture.timeperframe.numerator = 1000;
    parm.parm.capture.timeperframe.denominator =
        static_cast<std::uint32_t>(std::lround(fps * 1000));
    if (xioctl(fd, VIDIOC_S_PARM, &parm) != 0) throw_errno(device, "VIDIOC_S_PARM", errno);
  }
  const v4l2_fract t = parm.parm.capture.timeperframe;
  return t.numerator == 0 ? 0.0 : static_cast<double>(t.denominator) / t.numerator;
}

// Capture time: the driver's timestamp where it is on CLOCK_MONOTONIC (the steady clock's clock
// on Linux), so latency includes the time the frame waited in the driver; else the moment of
// dequeue.
Clock::time_point capture_time(const v4l2_buffer& b, Clock::time_point dequeued) {
  if ((b.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC &&
      (b.timestamp.tv_sec != 0 || b.timestamp.tv_usec != 0)) {
    const Clock::time_point stamped{std::chrono::duration_cast<Clock::duration>(
        std::chrono::seconds(b.timestamp.tv_sec) + std::chrono::microseconds(b.timestamp.tv_usec))};
    if (stamped <= dequeued && dequeued - stamped < std::chrono::seconds(10)) return stamped;
  }
  return dequeued;
}

}  // namespace

struct V4l2Capture::Impl {
  detail::V4l2Fd fd;
  std::string path, card;
  FrameLayout layout;
  double fps = 0;
  int timeout_ms = 3000;
  std::vector<MappedBuffer> buffers;
  bool streaming = false;
  Clock::time_point origin;
  std::int64_t returned = 0;
  std::int64_t extra_dropped = 0;  // bad frames skipped
  std::optional<std::uint32_t> first_sequence;
  std::uint32_t last_sequence = 0;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Also what cleans up after a constructor that threw half way.
  ~Impl() { stop(); }

  void queue(std::uint32_t index) {
    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = index;
    if (xioctl(fd.get(), VIDIOC_QBUF, &b) != 0) throw_errno(path, "VIDIOC_QBUF", errno);
  }

  // Waits for the device to be readable; returns what poll() saw (revents).
  short wait() {
    for (;;) {
      pollfd p{fd.get(), POLLIN, 0};
      const int r = ::poll(&p, 1, timeout_ms);
      if (r < 0) {
        if (errno == EINTR) continue;  // a signal: the caller checks its own stop flag per frame
        throw_errno(path, "poll", errno);
      }
      if (r == 0) {
        throw Error(ErrorKind::device,
                    fmt::format("{}: no frame for {} ms: camera stalled or disconnected", path,
                                timeout_ms));
      }
      return p.revents;
    }
  }

  // Drain: keep the newest filled buffer, hand older ones straight back (they are drops).
  std::optional<v4l2_buffer> dequeue_newest() {
    std::optional<v4l2_buffer> newest;
    for (;;) {
      v4l2_buffer b{};
      b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
      b.memory = V4L2_MEMORY_MMAP;
      if (xioctl(fd.get(), VIDIOC_DQBUF, &b) != 0) {
        if (errno == EAGAIN) break;
        throw_errno(path, "VIDIOC_DQBUF", errno);
      }
      if (newest) queue(newest->index);
      newest = b;
    }
    return newest;
  }

  void stop() noexcept {
    if (streaming) {
      int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
      xioctl(fd.get(), VIDIOC_STREAMOFF, &type);
      streaming = false;
    }
    detail::unmap_buffers(buffers);
    fd.reset();
  }
};

V4l2Capture::V4l2Capture(const std::string& device, const V4l2CaptureOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = device;
  m.timeout_ms = options.timeout_ms;
  if (options.buffers < 2 || options.buffers > 32) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: buffer count must be in 2..32 (got {})", device, options.buffers));
  }
  const V4l2DeviceInfo info = query_v4l2_device(device);
  m.card = info.card;
  check_capture_device(device, info);
  m.fd = detail::open_v4l2(device);
  const int fd = m.fd.get();

  if (options.input >= 0) {
    int input = options.input;
    if (xioctl(fd, VIDIOC_S_INPUT, &input) != 0) throw_errno(device, "VIDIOC_S_INPUT", errno);
  }
  m.layout = set_format(fd, device, choose_format(device, info, options), options.size);
  m.fps = set_frame_rate(fd, device, options.fps);

  detail::map_buffers(fd, device, V4L2_BUF_TYPE_VIDEO_CAPTURE,
                      static_cast<std::uint32_t>(options.buffers), m.buffers);
  for (std::uint32_t i = 0; i < m.buffers.size(); ++i) m.queue(i);
  m.origin = Clock::now();
}

V4l2Capture::~V4l2Capture() = default;

std::optional<Frame> V4l2Capture::read() {
  Impl& m = *impl_;
  const int fd = m.fd.get();
  if (!m.streaming) {
    // Streaming starts with the first read, not at construction: the work between the two
    // (computing the steal map) must not count as frames dropped or as latency.
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(fd, VIDIOC_STREAMON, &type) != 0) throw_errno(m.path, "VIDIOC_STREAMON", errno);
    m.streaming = true;
    m.origin = Clock::now();
  }
  int bad = 0;
  for (;;) {
    const short revents = m.wait();
    const std::optional<v4l2_buffer> newest = m.dequeue_newest();
    const Clock::time_point dequeued = Clock::now();
    if (!newest) {
      if ((revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
        throw Error(ErrorKind::device,
                    fmt::format("{}: device reported an error while streaming", m.path));
      }
      continue;  // woken without a frame
    }
    const v4l2_buffer b = *newest;
    if (!m.first_sequence) m.first_sequence = b.sequence;
    m.last_sequence = b.sequence;
    if ((b.flags & V4L2_BUF_FLAG_ERROR) != 0 || b.bytesused == 0 || b.index >= m.buffers.size()) {
      m.queue(b.index);
      ++m.extra_dropped;
      if (++bad > kMaxBadFrames) {
        throw Error(ErrorKind::device, fmt::format("{}: {} corrupt frames in a row", m.path, bad));
      }
      continue;
    }
    Frame frame;
    try {
      const auto* data = static_cast<const std::uint8_t*>(m.buffers[b.index].start);
      frame.image = to_bgr({data, std::min<std::size_t>(b.bytesused, m.buffers[b.index].length)},
                           m.layout, m.path);
    } catch (const Error&) {
      // A frame that does not decode (a torn MJPEG frame) is skipped, not fatal, unless they
      // keep coming.
      m.queue(b.index);
      ++m.extra_dropped;
      if (++bad > kMaxBadFrames) throw;
      continue;
    }
    m.queue(b.index);
    frame.index = static_cast<std::int64_t>(b.sequence - *m.first_sequence);
    frame.timestamp = std::chrono::duration<double>(capture_time(b, dequeued) - m.origin).count();
    ++m.returned;
    return frame;
  }
}

cv::Size V4l2Capture::size() const {
  return impl_->layout.size;
}
double V4l2Capture::fps() const {
  return impl_->fps;
}
std::string V4l2Capture::name() const {
  return impl_->path;
}
std::chrono::steady_clock::time_point V4l2Capture::clock_origin() const {
  return impl_->origin;
}
PixelFormat V4l2Capture::format() const {
  return impl_->layout.format;
}
std::string V4l2Capture::card() const {
  return impl_->card;
}

std::int64_t V4l2Capture::dropped() const {
  const Impl& m = *impl_;
  if (!m.first_sequence) return 0;
  // Everything the driver sequenced but we did not return: drained buffers and the driver's own
  // drops (sequence gaps when no buffer was queued).
  const std::int64_t produced = static_cast<std::int64_t>(m.last_sequence - *m.first_sequence) + 1;
  return std::max<std::int64_t>(produced - m.returned, m.extra_dropped);
}

}  // namespace ifsfx::video
