// SPDX-License-Identifier: Apache-2.0
#include "video/v4l2_convert.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include <fmt/format.h>
#include <linux/videodev2.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::video {

namespace {

std::size_t stride_of(const FrameLayout& layout, int bytes_per_pixel) {
  const auto packed = static_cast<std::size_t>(layout.size.width) * bytes_per_pixel;
  return layout.bytes_per_line == 0 ? packed : layout.bytes_per_line;
}

void check_length(std::span<const std::uint8_t> data, std::size_t need, const FrameLayout& layout,
                  const std::string& where) {
  if (data.size() < need) {
    throw Error(ErrorKind::io,
                fmt::format("{}: short {} frame: {}x{} needs {} bytes (got {})", where,
                            fourcc_name(fourcc(layout.format)), layout.size.width,
                            layout.size.height, need, data.size()));
  }
}

// A read-only Mat over driver memory; OpenCV only reads through it.
cv::Mat wrap(std::span<const std::uint8_t> data, int rows, int cols, int type, std::size_t step) {
  return cv::Mat(rows, cols, type, const_cast<std::uint8_t*>(data.data()), step);
}

// BT.601 limited range from 8-bit R'G'B' (Rec. 601 §2.5.4 scaled to 8 bits): the coefficients
// 65.481/255, 128.553/255, 24.966/255 for Y and 112/255 for the chroma extremes, in 16-bit fixed
// point with rounding.
constexpr int kShift = 16;
constexpr int kHalf = 1 << (kShift - 1);
constexpr int fixed(double c) {
  return static_cast<int>(c * (1 << kShift) + (c < 0 ? -0.5 : 0.5));
}
constexpr int kYR = fixed(65.481 / 255), kYG = fixed(128.553 / 255), kYB = fixed(24.966 / 255);
constexpr int kUR = fixed(-37.797 / 255), kUG = fixed(-74.203 / 255), kUB = fixed(112.0 / 255);
constexpr int kVR = fixed(112.0 / 255), kVG = fixed(-93.786 / 255), kVB = fixed(-18.214 / 255);

inline std::uint8_t luma(int r, int g, int b) {
  return static_cast<std::uint8_t>(((kYR * r + kYG * g + kYB * b + kHalf) >> kShift) + 16);
}
// Chroma of the sum of two pixels: the coefficients halved by one more bit of shift.
inline std::uint8_t chroma2(int c_r, int c_g, int c_b, int r2, int g2, int b2) {
  const int v = ((c_r * r2 + c_g * g2 + c_b * b2 + (1 << kShift)) >> (kShift + 1)) + 128;
  return static_cast<std::uint8_t>(std::clamp(v, 0, 255));
}

void bgr_to_yuyv(const cv::Mat& bgr, std::vector<std::uint8_t>& out) {
  const int w = bgr.cols, h = bgr.rows;
  out.resize(static_cast<std::size_t>(w) * h * 2);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* p = bgr.ptr<std::uint8_t>(y);
    std::uint8_t* q = out.data() + static_cast<std::size_t>(y) * w * 2;
    for (int x = 0; x < w; x += 2) {
      const int b0 = p[0], g0 = p[1], r0 = p[2];
      // An odd last column pairs with itself.
      const int b1 = x + 1 < w ? p[3] : b0, g1 = x + 1 < w ? p[4] : g0, r1 = x + 1 < w ? p[5] : r0;
      const int r2 = r0 + r1, g2 = g0 + g1, b2 = b0 + b1;
      q[0] = luma(r0, g0, b0);
      q[1] = chroma2(kUR, kUG, kUB, r2, g2, b2);
      q[2] = luma(r1, g1, b1);
      q[3] = chroma2(kVR, kVG, kVB, r2, g2, b2);
      p += 6;
      q += 4;
    }
  }
}

}  // namespace

std::uint32_t fourcc(PixelFormat format) {
  switch (format) {
    case PixelFormat::yuyv:
      return V4L2_PIX_FMT_YUYV;
    case PixelFormat::uyvy:
      return V4L2_PIX_FMT_UYVY;
    case PixelFormat::nv12:
      return V4L2_PIX_FMT_NV12;
    case PixelFormat::yuv420:
      return V4L2_PIX_FMT_YUV420;
    case PixelFormat::rgb24:
      return V4L2_PIX_FMT_RGB24;
    case PixelFormat::bgr24:
      return V4L2_PIX_FMT_BGR24;
    case PixelFormat::mjpeg:
      return V4L2_PIX_FMT_MJPEG;
  }
  return 0;
}

std::optional<PixelFormat> pixel_format_from_fourcc(std::uint32_t code) {
  switch (code) {
    case V4L2_PIX_FMT_YUYV:
      return PixelFormat::yuyv;
    case V4L2_PIX_FMT_UYVY:
      return PixelFormat::uyvy;
    case V4L2_PIX_FMT_NV12:
      return PixelFormat::nv12;
    case V4L2_PIX_FMT_YUV420:
      return PixelFormat::yuv420;
    case V4L2_PIX_FMT_RGB24:
      return PixelFormat::rgb24;
    case V4L2_PIX_FMT_BGR24:
      return PixelFormat::bgr24;
    // Plain JPEG frames are MJPEG frames to a decoder.
    case V4L2_PIX_FMT_MJPEG:
    case V4L2_PIX_FMT_JPEG:
      return PixelFormat::mjpeg;
    default:
      return std::nullopt;
  }
}

std::string fourcc_name(std::uint32_t code) {
  std::string name(4, ' ');
  for (int i = 0; i < 4; ++i) {
    const auto c = static_cast<char>((code >> (8 * i)) & 0xff);
    name[i] = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  while (!name.empty() && name.back() == ' ') name.pop_back();
  return name;
}

PixelFormat parse_pixel_format(const std::string& text, const std::string& what) {
  std::string t = text;
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
  if (t == "yuyv" || t == "yuy2") return PixelFormat::yuyv;
  if (t == "uyvy") return PixelFormat::uyvy;
  if (t == "nv12") return PixelFormat::nv12;
  if (t == "yuv420" || t == "i420" || t == "yu12") return PixelFormat::yuv420;
  if (t == "rgb24" || t == "rgb3") return PixelFormat::rgb24;
  if (t == "bgr24" || t == "bgr3") return PixelFormat::bgr24;
  if (t == "mjpeg" || t == "mjpg") return PixelFormat::mjpeg;
  throw Error(ErrorKind::parse,
              fmt::format("{}: unknown pixel format, expected yuyv, uyvy, nv12, yuv420, rgb24, "
                          "bgr24 or mjpeg (got '{}')",
                          what, text));
}

std::size_t frame_bytes(const FrameLayout& layout) {
  const auto h = static_cast<std::size_t>(layout.size.height);
  switch (layout.format) {
    case PixelFormat::yuyv:
    case PixelFormat::uyvy:
      return stride_of(layout, 2) * h;
    case PixelFormat::rgb24:
    case PixelFormat::bgr24:
      return stride_of(layout, 3) * h;
    case PixelFormat::nv12:
      return stride_of(layout, 1) * (h + (h + 1) / 2);
    case PixelFormat::yuv420: {
      const std::size_t s = stride_of(layout, 1);
      return s * h + 2 * (s / 2) * ((h + 1) / 2);
    }
    case PixelFormat::mjpeg:
      return 0;
  }
  return 0;
}

cv::Mat to_bgr(std::span<const std::uint8_t> data, const FrameLayout& layout,
               const std::string& where) {
  const int w = layout.size.width, h = layout.size.height;
  if (w <= 0 || h <= 0) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame size must be positive (got {}x{})", where, w, h));
  }
  check_length(data, frame_bytes(layout), layout, where);
  cv::Mat bgr;
  switch (layout.format) {
    case PixelFormat::yuyv:
      cv::cvtColor(wrap(data, h, w, CV_8UC2, stride_of(layout, 2)), bgr, cv::COLOR_YUV2BGR_YUYV);
      break;
    case PixelFormat::uyvy:
      cv::cvtColor(wrap(data, h, w, CV_8UC2, stride_of(layout, 2)), bgr, cv::COLOR_YUV2BGR_UYVY);
      break;
    case PixelFormat::rgb24:
      cv::cvtColor(wrap(data, h, w, CV_8UC3, stride_of(layout, 3)), bgr, cv::COLOR_RGB2BGR);
      break;
    case PixelFormat::bgr24:
      wrap(data, h, w, CV_8UC3, stride_of(layout, 3)).copyTo(bgr);
      break;
    case PixelFormat::nv12:
      // Y rows then interleaved UV rows, all of the same stride: one (3h/2)×w plane to OpenCV.
      cv::cvtColor(wrap(data, h * 3 / 2, w, CV_8UC1, stride_of(layout, 1)), bgr,
                   cv::COLOR_YUV2BGR_NV12);
      break;
    case PixelFormat::yuv420: {
      const std::size_t s = stride_of(layout, 1);
      if (s == static_cast<std::size_t>(w)) {
        cv::cvtColor(wrap(data, h * 3 / 2, w, CV_8UC1, s), bgr, cv::COLOR_YUV2BGR_I420);
        break;
      }
      // Padded rows: OpenCV wants the planes packed, so repack them first.
      std::vector<std::uint8_t> packed(static_cast<std::size_t>(w) * h * 3 / 2);
      std::uint8_t* q = packed.data();
      for (int y = 0; y < h; ++y, q += w) std::memcpy(q, data.data() + y * s, w);
      const std::uint8_t* chroma = data.data() + s * h;
      for (int plane = 0; plane < 2; ++plane) {
        for (int y = 0; y < h / 2; ++y, q += w / 2) std::memcpy(q, chroma + y * (s / 2), w / 2);
        chroma += (s / 2) * ((h + 1) / 2);
      }
      cv::cvtColor(cv::Mat(h * 3 / 2, w, CV_8UC1, packed.data()), bgr, cv::COLOR_YUV2BGR_I420);
      break;
    }
    case PixelFormat::mjpeg: {
      try {
        bgr = cv::imdecode(wrap(data, 1, static_cast<int>(data.size()), CV_8UC1, data.size()),
                           cv::IMREAD_COLOR);
      } catch (const cv::Exception&) {
        bgr.release();
      }
      if (bgr.empty()) {
        throw Error(ErrorKind::io, fmt::format("{}: corrupt MJPEG frame ({} bytes do not decode)",
                                               where, data.size()));
      }
      if (bgr.size() != layout.size) {
        throw Error(ErrorKind::io, fmt::format("{}: MJPEG frame is {}x{}, the format says {}x{}",
                                               where, bgr.cols, bgr.rows, w, h));
      }
      break;
    }
  }
  return bgr;
}

void from_bgr(const cv::Mat& bgr, PixelFormat format, std::vector<std::uint8_t>& out) {
  if (bgr.type() != CV_8UC3 || bgr.empty()) {
    throw Error(ErrorKind::invalid_argument,
                fmt::format("from_bgr: image must be 8-bit BGR (got type {}, {}x{})", bgr.type(),
                            bgr.cols, bgr.rows));
  }
  switch (format) {
    case PixelFormat::yuyv:
      bgr_to_yuyv(bgr, out);
      return;
    case PixelFormat::yuv420: {
      if (bgr.cols % 2 != 0 || bgr.rows % 2 != 0) {
        throw Error(
            ErrorKind::invalid_argument,
            fmt::format("from_bgr: YUV420 needs even sides (got {}x{})", bgr.cols, bgr.rows));
      }
      out.resize(static_cast<std::size_t>(bgr.cols) * bgr.rows * 3 / 2);
      cv::Mat dst(bgr.rows * 3 / 2, bgr.cols, CV_8UC1, out.data());
      cv::cvtColor(bgr, dst, cv::COLOR_BGR2YUV_I420);
      return;
    }
    default:
      throw Error(ErrorKind::unsupported,
                  fmt::format("from_bgr: output format {} not supported, use yuyv or yuv420",
                              fourcc_name(fourcc(format))));
  }
}

}  // namespace ifsfx::video
