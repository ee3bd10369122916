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

// OBS's matrix for cv::transform, which rounds and saturates to bytes in SIMD: `to_bgr` takes
// (y, u, v) bytes to (b, g, r) bytes (M's rows in BGR order, the constant scaled to bytes),
// `to_yuv` is its inverse; each sample is first clamped to the frame's range [lo, hi], as OBS's
// shader does.
struct Colours {
  cv::Matx34f to_bgr, to_yuv;
  cv::Scalar lo, hi;

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
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) to_bgr(2 - c, k) = F(c, k), to_yuv(c, 2 - k) = B(c, k);
      to_bgr(2 - c, 3) = offset[c], to_yuv(c, 3) = -back[c];
    }
    for (std::size_t k = 0; k < 3; ++k) {
      lo[static_cast<int>(k)] = std::ceil(255.0 * yuv.range_min[k] - 1e-3);
      hi[static_cast<int>(k)] = std::floor(255.0 * yuv.range_max[k] + 1e-3);
    }
  }
};

// Each column twice: chroma sampled once per two pixels, to `width` pixels.
cv::Mat widen(const cv::Mat& half, int width, int height) {
  cv::Mat wide;
  cv::resize(half, wide, {half.cols * 2, half.rows * (half.rows == height ? 1 : 2)}, 0, 0,
             cv::INTER_NEAREST);
  return wide(cv::Rect(0, 0, width, height));
}

// The Y, U and V samples of each pixel of a YUV frame, chroma by nearest sample.
std::vector<cv::Mat> full_planes(PixelFormat format, const std::vector<cv::Mat>& p, cv::Size size) {
  switch (format) {
    case PixelFormat::nv12: {
      cv::Mat uv[2];
      cv::split(p[1], uv);
      return {p[0], widen(uv[0], size.width, size.height), widen(uv[1], size.width, size.height)};
    }
    case PixelFormat::i420:
      return {p[0], widen(p[1], size.width, size.height), widen(p[2], size.width, size.height)};
    case PixelFormat::yuy2:
    case PixelFormat::uyvy: {
      cv::Mat m[4];  // Y0 U Y1 V, or U Y0 V Y1
      cv::split(p[0], m);
      const bool yuyv = format == PixelFormat::yuy2;
      cv::Mat pairs;
      cv::merge(std::vector<cv::Mat>{m[yuyv ? 0 : 1], m[yuyv ? 2 : 3]}, pairs);
      const cv::Mat luma = pairs.reshape(1, size.height)(cv::Rect(0, 0, size.width, size.height));
      return {luma, widen(m[yuyv ? 1 : 0], size.width, size.height),
              widen(m[yuyv ? 3 : 2], size.width, size.height)};
    }
    default:
      return {p[0], p[1], p[2]};
  }
}

// Writes luma `Y` (size of the frame) into the planes.
void write_luma(PixelFormat format, const cv::Mat& Y, std::vector<cv::Mat>& p) {
  if (format != PixelFormat::yuy2 && format != PixelFormat::uyvy) return Y.copyTo(p[0]);
  // Pairs of pixels into the macropixels' two luma bytes.
  cv::Mat even = Y;
  if (Y.cols % 2) cv::copyMakeBorder(Y, even, 0, 0, 0, 1, cv::BORDER_REPLICATE);
  cv::Mat pairs[2];
  cv::split(even.reshape(2, Y.rows), pairs);
  const int first = format == PixelFormat::yuy2 ? 0 : 1;
  const int from_to[] = {0, first, 1, first + 2};
  const cv::Mat sources[] = {pairs[0], pairs[1]};
  cv::mixChannels(sources, 2, &p[0], 1, from_to, 2);
}

// Writes chroma `UV` (CV_8UC2, the chroma grid's size) into the planes.
void write_chroma(PixelFormat format, const cv::Mat& UV, std::vector<cv::Mat>& p) {
  switch (format) {
    case PixelFormat::nv12:
      UV.copyTo(p[1]);
      return;
    case PixelFormat::yuy2:
    case PixelFormat::uyvy: {
      const int u = format == PixelFormat::yuy2 ? 1 : 0;
      const int from_to[] = {0, u, 1, u + 2};
      cv::mixChannels(&UV, 1, &p[0], 1, from_to, 2);
      return;
    }
    default: {
      cv::Mat* planes = &p[1];
      const int from_to[] = {0, 0, 1, 1};
      cv::mixChannels(&UV, 1, planes, 2, from_to, 2);
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
  cv::Mat samples;
  cv::merge(full_planes(format, planes, size), samples);
  cv::max(samples, colours.lo, samples);
  cv::min(samples, colours.hi, samples);
  cv::transform(samples, out, colours.to_bgr);
  return out;
}

void from_engine(const cv::Mat& picture, PixelFormat format, const YuvMatrix& yuv,
                 std::vector<cv::Mat>& planes) {
  if (format == PixelFormat::rgba) return cv::cvtColor(picture, planes[0], cv::COLOR_BGRA2RGBA);
  if (is_rgb(format)) return picture.copyTo(planes[0]);
  const Colours colours(yuv);
  cv::Mat samples;
  cv::transform(picture, samples, colours.to_yuv);
  cv::Mat Y;
  cv::extractChannel(samples, Y, 0);
  write_luma(format, Y, planes);
  // The chroma of a block is that of its pixels' mean colour.
  const Subsampling s = subsampling(format);
  if (s.x > 1 || s.y > 1) {
    // An odd last column or row is a block of its own: repeated, its mean is its own colour.
    cv::Mat even = picture, mean;
    const int right = s.x > 1 ? picture.cols % 2 : 0, bottom = s.y > 1 ? picture.rows % 2 : 0;
    if (right || bottom)
      cv::copyMakeBorder(picture, even, 0, bottom, 0, right, cv::BORDER_REPLICATE);
    cv::resize(even, mean, {even.cols / s.x, even.rows / s.y}, 0, 0, cv::INTER_AREA);
    cv::transform(mean, samples, colours.to_yuv);
  }
  cv::Mat UV;
  const int from_to[] = {1, 0, 2, 1};
  UV.create(samples.size(), CV_8UC2);
  cv::mixChannels(&samples, 1, &UV, 1, from_to, 2);
  write_chroma(format, UV, planes);
}

}  // namespace ifsfx::obs
