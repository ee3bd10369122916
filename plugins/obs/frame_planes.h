// SPDX-License-Identifier: Apache-2.0
// A video frame in CPU memory as OBS hands it to an async filter (struct obs_source_frame), seen
// as one cv::Mat per plane, and its conversion to the engine's BGR(A) and back. Free of libobs,
// so that the conversions are tested without it.
//
// YUV frames carry OBS's colour matrix: rgb = M · (y, u, v, 1) with every value in [0, 1] and
// y, u, v first clamped to the frame's range (OBS's format_conversion.effect, YUV_to_RGB). The way
// back uses M's inverse, so a frame of any colour space and range comes back in its own.
//
//   const std::vector<cv::Mat> planes = wrap_planes(PixelFormat::nv12, size, data, linesize);
//   cv::Mat bgr = to_engine(PixelFormat::nv12, planes, yuv);  // ... filter ...
//   from_engine(bgr, PixelFormat::nv12, yuv, planes);           // written in place
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::obs {

// The formats converted (OBS's VIDEO_FORMAT_*); any other passes through unfiltered.
enum class PixelFormat { nv12, i420, yuy2, uyvy, rgba, bgra, bgrx, i444 };

// OBS's YUV → RGB parameters of a frame (obs_source_frame's color_matrix, row-major 4×4, and
// color_range_min/max): ignored for the RGB formats.
struct YuvMatrix {
  std::array<float, 16> matrix{};
  std::array<float, 3> range_min{0, 0, 0};
  std::array<float, 3> range_max{1, 1, 1};
};

// The planes of a `size` frame of `format` over `data` and `linesize` (OBS's arrays, one entry
// per plane), not copied: 4:2:0 chroma is ⌈w/2⌉×⌈h/2⌉; YUY2 and UYVY are one CV_8UC4 plane of
// ⌈w/2⌉×h macropixels (two luma samples and one chroma pair each).
std::vector<cv::Mat> wrap_planes(PixelFormat format, cv::Size size, const std::uint8_t* const* data,
                                 const std::uint32_t* linesize);

// The frame in the engine's layout: CV_8UC4 for RGBA, BGRA and BGRX (as BGRA; the fourth channel
// passes through the filter), CV_8UC3 BGR for the YUV formats.
cv::Mat to_engine(PixelFormat format, const std::vector<cv::Mat>& planes, const YuvMatrix& yuv,
                  cv::Size size);

// Writes the engine's picture (what to_engine gave, filtered) back into `planes` of `format`.
// 4:2:0 and 4:2:2 chroma is the mean of the pixels it covers.
void from_engine(const cv::Mat& picture, PixelFormat format, const YuvMatrix& yuv,
                 std::vector<cv::Mat>& planes);

}  // namespace ifsfx::obs
