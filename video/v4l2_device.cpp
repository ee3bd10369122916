// SPDX-License-Identifier: Apache-2.0
#include "video/v4l2_device.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/videodev2.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "ifs/error.h"

namespace ifsfx::video {

namespace detail {

V4l2Fd::V4l2Fd(V4l2Fd&& other) noexcept : fd_(other.fd_), path_(std::move(other.path_)) {
  other.fd_ = -1;
}

V4l2Fd& V4l2Fd::operator=(V4l2Fd&& other) noexcept {
  if (this != &other) {
    reset();
    fd_ = other.fd_;
    path_ = std::move(other.path_);
    other.fd_ = -1;
  }
  return *this;
}

V4l2Fd::~V4l2Fd() {
  reset();
}

void V4l2Fd::reset() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

int xioctl(int fd, unsigned long request, void* arg) {
  int r = 0;
  do {
    r = ::ioctl(fd, request, arg);
  } while (r == -1 && errno == EINTR);
  return r;
}

void throw_errno(const std::string& path, const std::string& what, int err) {
  const char* name = strerrorname_np(err);
  const std::string detail = fmt::format("{} ({})", std::strerror(err), name ? name : "?");
  switch (err) {
    case ENOENT:
    case ENXIO:
      throw Error(ErrorKind::not_found, fmt::format("{}: no such device: {}", path, detail));
    case ENODEV:
      throw Error(ErrorKind::device,
                  fmt::format("{}: device vanished ({} failed: {})", path, what, detail));
    case EBUSY:
      throw Error(ErrorKind::device,
                  fmt::format("{}: device busy, in use by another program ({} failed: {})", path,
                              what, detail));
    case ENOTTY:
      throw Error(ErrorKind::unsupported,
                  fmt::format("{}: not a V4L2 video device ({} failed: {})", path, what, detail));
    default:
      throw Error(ErrorKind::device, fmt::format("{}: {} failed: {}", path, what, detail));
  }
}

V4l2Fd open_v4l2(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw_errno(path, "open", errno);
  return V4l2Fd(fd, path);
}

void map_buffers(int fd, const std::string& path, std::uint32_t buffer_type, std::uint32_t count,
                 std::vector<MappedBuffer>& out) {
  const auto type = static_cast<v4l2_buf_type>(buffer_type);
  v4l2_requestbuffers req{};
  req.count = count;
  req.type = type;
  req.memory = V4L2_MEMORY_MMAP;
  if (xioctl(fd, VIDIOC_REQBUFS, &req) != 0) throw_errno(path, "VIDIOC_REQBUFS", errno);
  if (req.count < 2)
    throw Error(ErrorKind::device,
                fmt::format("{}: driver granted {} {} buffer(s), streaming needs 2", path,
                            req.count, type == V4L2_BUF_TYPE_VIDEO_OUTPUT ? "output" : "capture"));
  for (std::uint32_t i = 0; i < req.count; ++i) {
    v4l2_buffer b{};
    b.type = type;
    b.memory = V4L2_MEMORY_MMAP;
    b.index = i;
    if (xioctl(fd, VIDIOC_QUERYBUF, &b) != 0) throw_errno(path, "VIDIOC_QUERYBUF", errno);
    void* start = mmap(nullptr, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd, b.m.offset);
    if (start == MAP_FAILED) throw_errno(path, "mmap", errno);
    out.push_back({start, b.length});
  }
}

void unmap_buffers(std::vector<MappedBuffer>& buffers) noexcept {
  for (const MappedBuffer& m : buffers) munmap(m.start, m.length);
  buffers.clear();
}

}  // namespace detail

namespace {

using detail::xioctl;

std::string text_of(const __u8* chars, std::size_t n) {
  const auto* c = reinterpret_cast<const char*>(chars);
  return std::string(c, strnlen(c, n));
}

double fps_of(const v4l2_fract& interval) {
  return interval.numerator == 0 ? 0.0
                                 : static_cast<double>(interval.denominator) / interval.numerator;
}

std::vector<double> enum_rates(int fd, std::uint32_t code, cv::Size size, bool& stepwise) {
  std::vector<double> fps;
  stepwise = false;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_frmivalenum ival{};
    ival.index = i;
    ival.pixel_format = code;
    ival.width = static_cast<std::uint32_t>(size.width);
    ival.height = static_cast<std::uint32_t>(size.height);
    if (xioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &ival) != 0) break;
    if (ival.type == V4L2_FRMIVAL_TYPE_DISCRETE) {
      fps.push_back(fps_of(ival.discrete));
    } else {
      // Continuous or stepwise: the shortest interval is the highest rate.
      fps = {fps_of(ival.stepwise.min), fps_of(ival.stepwise.max)};
      stepwise = true;
      break;
    }
  }
  std::sort(fps.begin(), fps.end(), std::greater<>());
  return fps;
}

std::vector<V4l2Format> enum_formats(int fd, v4l2_buf_type type) {
  std::vector<V4l2Format> formats;
  for (std::uint32_t i = 0;; ++i) {
    v4l2_fmtdesc desc{};
    desc.index = i;
    desc.type = type;
    if (xioctl(fd, VIDIOC_ENUM_FMT, &desc) != 0) break;
    V4l2Format f;
    f.fourcc = desc.pixelformat;
    f.description = text_of(desc.description, sizeof desc.description);
    f.compressed = (desc.flags & V4L2_FMT_FLAG_COMPRESSED) != 0;
    for (std::uint32_t j = 0;; ++j) {
      v4l2_frmsizeenum fs{};
      fs.index = j;
      fs.pixel_format = desc.pixelformat;
      if (xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &fs) != 0) break;
      if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
        V4l2FrameSize s;
        s.size = {static_cast<int>(fs.discrete.width), static_cast<int>(fs.discrete.height)};
        s.fps = enum_rates(fd, f.fourcc, s.size, s.stepwise_rates);
        f.sizes.push_back(std::move(s));
      } else {
        f.stepwise_sizes = true;
        for (const cv::Size size : {cv::Size(static_cast<int>(fs.stepwise.min_width),
                                             static_cast<int>(fs.stepwise.min_height)),
                                    cv::Size(static_cast<int>(fs.stepwise.max_width),
                                             static_cast<int>(fs.stepwise.max_height))}) {
          V4l2FrameSize s;
          s.size = size;
          s.fps = enum_rates(fd, f.fourcc, size, s.stepwise_rates);
          f.sizes.push_back(std::move(s));
        }
        break;
      }
    }
    formats.push_back(std::move(f));
  }
  return formats;
}

}  // namespace

V4l2DeviceInfo query_v4l2_device(const std::string& path) {
  const detail::V4l2Fd fd = detail::open_v4l2(path);
  v4l2_capability cap{};
  if (xioctl(fd.get(), VIDIOC_QUERYCAP, &cap) != 0)
    detail::throw_errno(path, "VIDIOC_QUERYCAP", errno);
  const std::uint32_t caps =
      (cap.capabilities & V4L2_CAP_DEVICE_CAPS) != 0 ? cap.device_caps : cap.capabilities;
  V4l2DeviceInfo info;
  info.path = path;
  info.driver = text_of(cap.driver, sizeof cap.driver);
  info.card = text_of(cap.card, sizeof cap.card);
  info.bus = text_of(cap.bus_info, sizeof cap.bus_info);
  info.capture = (caps & V4L2_CAP_VIDEO_CAPTURE) != 0;
  info.output = (caps & V4L2_CAP_VIDEO_OUTPUT) != 0;
  info.streaming = (caps & V4L2_CAP_STREAMING) != 0;
  info.read_write = (caps & V4L2_CAP_READWRITE) != 0;
  if (info.capture) info.capture_formats = enum_formats(fd.get(), V4L2_BUF_TYPE_VIDEO_CAPTURE);
  if (info.output) info.output_formats = enum_formats(fd.get(), V4L2_BUF_TYPE_VIDEO_OUTPUT);
  return info;
}

std::vector<V4l2ListEntry> list_v4l2_devices(const std::filesystem::path& dev) {
  std::vector<std::pair<int, std::string>> nodes;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dev, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("video", 0) != 0 || name.size() == 5) continue;
    const std::string digits = name.substr(5);
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      continue;
    }
    nodes.emplace_back(std::stoi(digits), entry.path().string());
  }
  std::sort(nodes.begin(), nodes.end());
  std::vector<V4l2ListEntry> list;
  for (const auto& [number, path] : nodes) {
    V4l2ListEntry e;
    e.info.path = path;
    try {
      e.info = query_v4l2_device(path);
      // Metadata and other non-video nodes (e.g. a UVC camera's second node) are not cameras.
      if (!e.info.capture && !e.info.output) continue;
    } catch (const Error& error) {
      e.error = error.what();
    }
    list.push_back(std::move(e));
  }
  return list;
}

}  // namespace ifsfx::video
