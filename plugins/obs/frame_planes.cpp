// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/frame_planes.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::obs {
namespace {

// Chroma samples per luma sample across and down.
struct Subsampling {
  int x = 1, y = 1;
};

Subsampling subsampling(PixelFormat format) {
  switch (format) {
    case PixelFormat::nv12:
    case PixelFormat::i420:
      return {2, 2};
    case PixelFormat::yuy2:
    case PixelFormat::uyvy:
      return {2, 1};
    default:
      return {1, 1};
  }
}

bool is_rgb(PixelFormat format) {
  return format == PixelFormat::rgba || format == PixelFormat::bgra || format == PixelFormat::bgrx;
}

std::uint8_t to_byte(float value) {
  return static_cast<std::uint8_t>(std::clamp(std::floor(value + 0.5f), 0.0f, 255.0f));
}

// OBS's matrix as tables of bytes: rgb = Σ_k F_k[yuv_k] (each term of M's row times the sample,
// clamped to the frame's range first, as OBS's shader does; the constant in the luma table), and
// the inverse, yuv = Σ_c B_c[rgb_c]. Linear, so a mean of samples is the mean of their terms.
class Colours {
 public:
  explicit Colours(const YuvMatrix& yuv) {
    const auto& m = yuv.matrix;
    cv::Matx33f F;
    cv::Vec3f offset;
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) F(c, k) = m[static_cast<std::size_t>(c * 4 + k)];
      offset[c] = 255.0f * m[static_cast<std::size_t>(c * 4 + 3)];
    }
    bool invertible = false;
    const cv::Matx33f B = F.inv(cv::DECOMP_LU, &invertible);
    if (!invertible)
      throw Error(ErrorKind::invalid_argument, "colour matrix: must be invertible (got singular)");
    const cv::Vec3f back = B * offset;
    for (int v = 0; v < 256; ++v)
      for (int k = 0; k < 3; ++k) {
        const auto K = static_cast<std::size_t>(k);
        const float lo = 255.0f * yuv.range_min[K], hi = 255.0f * yuv.range_max[K];
        const float sample = std::clamp(static_cast<float>(v), lo, hi);
        for (int c = 0; c < 3; ++c) {
          to_rgb_[K][static_cast<std::size_t>(v)][c] = F(c, k) * sample + (k == 0 ? offset[c] : 0);
          // From rgb channel k to yuv channel c; the offset with the red channel's table.
          to_yuv_[K][static_cast<std::size_t>(v)][c] =
              B(c, k) * static_cast<float>(v) - (k == 0 ? back[c] : 0);
        }
      }
  }

  // BGR bytes of one YUV sample.
  cv::Vec3b bgr(std::uint8_t y, std::uint8_t u, std::uint8_t v) const {
    const cv::Vec3f rgb = to_rgb_[0][y] + to_rgb_[1][u] + to_rgb_[2][v];
    return {to_byte(rgb[2]), to_byte(rgb[1]), to_byte(rgb[0])};
  }
  // YUV (unrounded) of BGR bytes.
  cv::Vec3f yuv(const cv::Vec3b& bgr) const {
    return to_yuv_[0][bgr[2]] + to_yuv_[1][bgr[1]] + to_yuv_[2][bgr[0]];
  }

 private:
  std::array<std::array<cv::Vec3f, 256>, 3> to_rgb_, to_yuv_;
};

// Row y of a YUV frame as one Y, U and V sample per pixel.
void read_row(PixelFormat format, const std::vector<cv::Mat>& p, int y, int width, std::uint8_t* Y,
              std::uint8_t* U, std::uint8_t* V) {
  switch (format) {
    case PixelFormat::nv12: {
      const std::uint8_t* uv = p[1].ptr(y / 2);
      std::copy_n(p[0].ptr(y), width, Y);
      for (int x = 0; x < width; ++x) U[x] = uv[(x / 2) * 2], V[x] = uv[(x / 2) * 2 + 1];
      return;
    }
    case PixelFormat::i420:
      std::copy_n(p[0].ptr(y), width, Y);
      for (int x = 0; x < width; ++x) U[x] = p[1].ptr(y / 2)[x / 2], V[x] = p[2].ptr(y / 2)[x / 2];
      return;
    case PixelFormat::yuy2:
    case PixelFormat::uyvy: {
      const std::uint8_t* m = p[0].ptr(y);
      const bool yuyv = format == PixelFormat::yuy2;  // Y0 U Y1 V, else U Y0 V Y1
      for (int x = 0; x < width; ++x) {
        const std::uint8_t* macro = m + (x / 2) * 4;
        Y[x] = macro[(yuyv ? 0 : 1) + (x & 1) * 2];
        U[x] = macro[yuyv ? 1 : 0], V[x] = macro[yuyv ? 3 : 2];
      }
      return;
    }
    default:
      std::copy_n(p[0].ptr(y), width, Y);
      std::copy_n(p[1].ptr(y), width, U);
      std::copy_n(p[2].ptr(y), width, V);
  }
}

void write_luma(PixelFormat format, std::vector<cv::Mat>& p, int y, const float* Y, int width) {
  if (format == PixelFormat::yuy2 || format == PixelFormat::uyvy) {
    std::uint8_t* m = p[0].ptr(y) + (format == PixelFormat::yuy2 ? 0 : 1);
    for (int x = 0; x < width; ++x) m[(x / 2) * 4 + (x & 1) * 2] = to_byte(Y[x]);
    return;
  }
  std::uint8_t* row = p[0].ptr(y);
  for (int x = 0; x < width; ++x) row[x] = to_byte(Y[x]);
}

// Chroma row cy: sample cx is (U[cx], V[cx]).
void write_chroma(PixelFormat format, std::vector<cv::Mat>& p, int cy, const float* U,
                  const float* V, int count) {
  for (int cx = 0; cx < count; ++cx) {
    const std::uint8_t u = to_byte(U[cx]), v = to_byte(V[cx]);
    switch (format) {
      case PixelFormat::nv12:
        p[1].ptr(cy)[2 * cx] = u, p[1].ptr(cy)[2 * cx + 1] = v;
        break;
      case PixelFormat::yuy2:
        p[0].ptr(cy)[4 * cx + 1] = u, p[0].ptr(cy)[4 * cx + 3] = v;
        break;
      case PixelFormat::uyvy:
        p[0].ptr(cy)[4 * cx] = u, p[0].ptr(cy)[4 * cx + 2] = v;
        break;
      default:
        p[1].ptr(cy)[cx] = u, p[2].ptr(cy)[cx] = v;
    }
  }
}

}  // namespace

std::vector<cv::Mat> wrap_planes(PixelFormat format, cv::Size size, const std::uint8_t* const* data,
                                 const std::uint32_t* linesize) {
  const cv::Size half((size.width + 1) / 2, (size.height + 1) / 2);
  auto plane = [&](int i, cv::Size s, int type) {
    return cv::Mat(s, type, const_cast<std::uint8_t*>(data[i]), linesize[i]);
  };
  switch (format) {
    case PixelFormat::nv12:
      return {plane(0, size, CV_8UC1), plane(1, half, CV_8UC2)};
    case PixelFormat::i420:
      return {plane(0, size, CV_8UC1), plane(1, half, CV_8UC1), plane(2, half, CV_8UC1)};
    case PixelFormat::yuy2:
    case PixelFormat::uyvy:
      return {plane(0, {half.width, size.height}, CV_8UC4)};
    case PixelFormat::i444:
      return {plane(0, size, CV_8UC1), plane(1, size, CV_8UC1), plane(2, size, CV_8UC1)};
    default:
      return {plane(0, size, CV_8UC4)};
  }
}

cv::Mat to_engine(PixelFormat format, const std::vector<cv::Mat>& planes, const YuvMatrix& yuv,
                  cv::Size size) {
  cv::Mat out;
  if (format == PixelFormat::rgba) {
    cv::cvtColor(planes[0], out, cv::COLOR_RGBA2BGRA);
    return out;
  }
  if (is_rgb(format)) return planes[0].clone();
  const Colours colours(yuv);
  out.create(size, CV_8UC3);
  std::vector<std::uint8_t> Y(static_cast<std::size_t>(size.width)), U(Y.size()), V(Y.size());
  for (int y = 0; y < size.height; ++y) {
    read_row(format, planes, y, size.width, Y.data(), U.data(), V.data());
    auto* row = out.ptr<cv::Vec3b>(y);
    for (std::size_t x = 0; x < Y.size(); ++x) row[x] = colours.bgr(Y[x], U[x], V[x]);
  }
  return out;
}

void from_engine(const cv::Mat& picture, PixelFormat format, const YuvMatrix& yuv,
                 std::vector<cv::Mat>& planes) {
  if (format == PixelFormat::rgba) return cv::cvtColor(picture, planes[0], cv::COLOR_BGRA2RGBA);
  if (is_rgb(format)) return picture.copyTo(planes[0]);
  const Colours colours(yuv);
  const Subsampling s = subsampling(format);
  const int width = picture.cols, chroma_width = (width + s.x - 1) / s.x;
  std::vector<float> Y(static_cast<std::size_t>(width));
  std::vector<float> U(static_cast<std::size_t>(chroma_width)), V(U.size());
  std::vector<int> n(U.size());
  for (int cy = 0; cy < (picture.rows + s.y - 1) / s.y; ++cy) {
    std::fill(U.begin(), U.end(), 0.0f), std::fill(V.begin(), V.end(), 0.0f);
    std::fill(n.begin(), n.end(), 0);
    // The chroma of a block is the mean of its pixels'.
    for (int y = cy * s.y; y < std::min(picture.rows, (cy + 1) * s.y); ++y) {
      const auto* row = picture.ptr<cv::Vec3b>(y);
      for (int x = 0; x < width; ++x) {
        const cv::Vec3f c = colours.yuv(row[x]);
        const auto cx = static_cast<std::size_t>(x / s.x);
        Y[static_cast<std::size_t>(x)] = c[0], U[cx] += c[1], V[cx] += c[2], ++n[cx];
      }
      write_luma(format, planes, y, Y.data(), width);
    }
    for (std::size_t cx = 0; cx < U.size(); ++cx) U[cx] /= float(n[cx]), V[cx] /= float(n[cx]);
    write_chroma(format, planes, cy, U.data(), V.data(), chroma_width);
  }
}

}  // namespace ifsfx::obs
