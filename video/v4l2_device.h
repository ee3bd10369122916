// SPDX-License-Identifier: Apache-2.0
// V4L2 device nodes on the kernel API (linux/videodev2.h): opening one with errno turned into
// ifsfx::Error, and listing what a device offers (VIDIOC_QUERYCAP, VIDIOC_ENUM_FMT,
// VIDIOC_ENUM_FRAMESIZES, VIDIOC_ENUM_FRAMEINTERVALS) for `ifsfx cam --list`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::video {

// Frame sizes a format offers at one size: the frame rates in frames per second, highest first.
// A stepwise/continuous interval range is given as {max, min}; `stepwise_rates` says so.
struct V4l2FrameSize {
  cv::Size size;
  std::vector<double> fps;
  bool stepwise_rates = false;
};

struct V4l2Format {
  std::uint32_t fourcc = 0;
  std::string description;  // the driver's, e.g. "YUYV 4:2:2"
  bool compressed = false;
  std::vector<V4l2FrameSize> sizes;  // discrete sizes; for stepwise ones, the min and max size
  bool stepwise_sizes = false;
};

struct V4l2DeviceInfo {
  std::string path;  // "/dev/video0"
  std::string driver, card, bus;
  bool capture = false;  // a video capture node (V4L2_CAP_VIDEO_CAPTURE)
  bool output = false;   // a video output node (V4L2_CAP_VIDEO_OUTPUT), e.g. v4l2loopback
  bool streaming = false;
  bool read_write = false;
  std::vector<V4l2Format> capture_formats;
  std::vector<V4l2Format> output_formats;
};

// Queries one node. Throws Error{not_found} when it does not exist, Error{unsupported} when it is
// not a V4L2 video node, Error{device} for other faults, naming the path.
V4l2DeviceInfo query_v4l2_device(const std::string& path);

// Every /dev/videoN under `dev` that answers QUERYCAP as a video capture or output node, in
// numeric order. Nodes that cannot be opened (busy, no permission) are listed with what could be
// read, never skipped silently: `error` says why.
struct V4l2ListEntry {
  V4l2DeviceInfo info;
  std::string error;  // empty when the query succeeded
};
std::vector<V4l2ListEntry> list_v4l2_devices(const std::filesystem::path& dev = "/dev");

namespace detail {

// An open device node; closes on destruction.
class V4l2Fd {
 public:
  V4l2Fd() = default;
  V4l2Fd(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  V4l2Fd(V4l2Fd&& other) noexcept;
  V4l2Fd& operator=(V4l2Fd&& other) noexcept;
  V4l2Fd(const V4l2Fd&) = delete;
  V4l2Fd& operator=(const V4l2Fd&) = delete;
  ~V4l2Fd();

  int get() const { return fd_; }
  const std::string& path() const { return path_; }
  void reset();

 private:
  int fd_ = -1;
  std::string path_;
};

// Opens a node read-write, non-blocking (reads are paced by poll()). Throws Error{not_found} for a
// missing node, Error{device} for busy or forbidden ones, naming the path.
V4l2Fd open_v4l2(const std::string& path);

// ioctl() retried on EINTR; returns -1 with errno set on failure.
int xioctl(int fd, unsigned long request, void* arg);

// The Error for a failed call: "PATH: WHAT failed: strerror (errno NAME)", of kind device, or
// not_found for ENOENT/ENXIO, or unsupported for ENOTTY; ENODEV reads "device vanished".
[[noreturn]] void throw_errno(const std::string& path, const std::string& what, int err);

// One driver buffer mapped into our memory (mmap streaming).
struct MappedBuffer {
  void* start = nullptr;
  std::size_t length = 0;
};

// Requests `count` mmap buffers of `buffer_type` (a v4l2_buf_type) with REQBUFS, maps each and
// appends it to `out` — also when a later step throws, so the caller's unmap_buffers frees what
// was mapped. Throws naming `path`, also when the driver grants fewer than 2 buffers.
void map_buffers(int fd, const std::string& path, std::uint32_t buffer_type, std::uint32_t count,
                 std::vector<MappedBuffer>& out);

// Unmaps and forgets every buffer of `buffers`.
void unmap_buffers(std::vector<MappedBuffer>& buffers) noexcept;

}  // namespace detail

}  // namespace ifsfx::video
