// SPDX-License-Identifier: Apache-2.0
// Pixel formats of V4L2 buffers and their conversions to and from the libraries' 8-bit BGR.
// Capture side: YUYV, UYVY, NV12, YUV420 (I420), RGB24, BGR24 and MJPEG buffers to BGR, with the
// driver's row stride (bytesperline) honoured. Output side: BGR to YUYV or YUV420, the formats
// browsers and video-call apps accept from a virtual webcam.
//
// YUV is ITU-R BT.601 limited range (Y in 16..235, U and V in 16..240), the convention of
// webcams, of V4L2's default colourspace for SDTV sizes and of OpenCV's YUV conversions, which the
// tests use as the reference.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::video {

enum class PixelFormat { yuyv, uyvy, nv12, yuv420, rgb24, bgr24, mjpeg };

// The V4L2 fourcc of a format (V4L2_PIX_FMT_YUYV, ...), and back (nothing for formats we do not
// convert).
std::uint32_t fourcc(PixelFormat format);
std::optional<PixelFormat> pixel_format_from_fourcc(std::uint32_t fourcc);

// The four characters of a fourcc, e.g. "YUYV", "MJPG" (non-printable bytes as '?').
std::string fourcc_name(std::uint32_t fourcc);

// Parses a format name as given on the command line: yuyv, uyvy, nv12, yuv420 (or i420, yu12),
// rgb24, bgr24, mjpeg (or mjpg); case-insensitive. Throws Error{parse} naming `what`.
PixelFormat parse_pixel_format(const std::string& text, const std::string& what = "format");

// How one frame lies in a buffer. `bytes_per_line` is the stride of the first plane (V4L2's
// bytesperline; 0 means tightly packed); chroma planes of NV12/YUV420 follow V4L2's single-plane
// layout (UV rows of the same stride for NV12, U then V planes at half the stride for YUV420).
struct FrameLayout {
  PixelFormat format = PixelFormat::yuyv;
  cv::Size size;
  std::size_t bytes_per_line = 0;
};

// Bytes a frame of this layout needs (for MJPEG: 0, the size varies per frame).
std::size_t frame_bytes(const FrameLayout& layout);

// Converts one buffer to 8-bit BGR (CV_8UC3) of layout.size. Throws Error{io} naming `where` for a
// buffer shorter than the layout needs, an MJPEG frame that does not decode, or one of another
// size than the layout's.
//   cv::Mat bgr = to_bgr({data, bytesused}, {PixelFormat::yuyv, {640, 480}, 1280}, "/dev/video0");
cv::Mat to_bgr(std::span<const std::uint8_t> data, const FrameLayout& layout,
               const std::string& where);

// Converts a BGR image (CV_8UC3) to a tightly packed YUYV or YUV420 buffer of its size, written
// into `out` (resized to fit). YUYV averages the chroma of each horizontal pixel pair; YUV420
// (through OpenCV) needs even sides. Throws Error{unsupported} for other formats and
// Error{invalid_argument} for an image that is not CV_8UC3 or odd-sized for YUV420.
void from_bgr(const cv::Mat& bgr, PixelFormat format, std::vector<std::uint8_t>& out);

}  // namespace ifsfx::video
