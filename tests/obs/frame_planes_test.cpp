// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/frame_planes.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace ifsfx::obs {
namespace {

// BT.709 in limited range, as OBS's matrix (rgb = M · (y, u, v, 1), all in [0, 1]): Kr = 0.2126,
// Kb = 0.0722, luma 16..235 and chroma 16..240 of 255, chroma centred on 128.
YuvMatrix bt709_limited() {
  const float kr = 0.2126f, kb = 0.0722f, kg = 1 - kr - kb;
  const float ys = 255.0f / 219, cs = 255.0f / 224, y0 = 16.0f / 255, c0 = 128.0f / 255;
  const float rv = cs * 2 * (1 - kr), bu = cs * 2 * (1 - kb);
  const float gu = -bu * kb / kg, gv = -rv * kr / kg;
  YuvMatrix m;
  m.matrix = {ys, 0,  rv, -ys * y0 - rv * c0,         //
              ys, gu, gv, -ys * y0 - (gu + gv) * c0,  //
              ys, bu, 0,  -ys * y0 - bu * c0,         //
              0,  0,  0,  1};
  m.range_min = {16.0f / 255, 16.0f / 255, 16.0f / 255};
  m.range_max = {235.0f / 255, 240.0f / 255, 240.0f / 255};
  return m;
}

// Random BGR in 2×2 blocks of one colour, so that no chroma subsampling loses anything.
cv::Mat blocky_picture(cv::Size size) {
  cv::Mat small((size.height + 1) / 2, (size.width + 1) / 2, CV_8UC3), big;
  cv::RNG rng(7);
  rng.fill(small, cv::RNG::UNIFORM, 0, 256);
  cv::resize(small, big, {small.cols * 2, small.rows * 2}, 0, 0, cv::INTER_NEAREST);
  return big(cv::Rect({0, 0}, size)).clone();
}

// Owned planes of `format` for a `size` frame, as OBS would hand them.
std::vector<cv::Mat> make_planes(PixelFormat format, cv::Size size,
                                 std::vector<std::vector<std::uint8_t>>& memory) {
  std::uint8_t* data[4] = {};
  std::uint32_t linesize[4] = {};
  const auto w = static_cast<std::uint32_t>(size.width + 8);  // padded rows, as OBS's may be
  memory.assign(3, std::vector<std::uint8_t>(w * 4 * static_cast<std::uint32_t>(size.height)));
  for (int i = 0; i < 3; ++i) data[i] = memory[static_cast<std::size_t>(i)].data();
  linesize[0] = w * 4, linesize[1] = w * 2, linesize[2] = w;
  if (format == PixelFormat::nv12 || format == PixelFormat::i420 || format == PixelFormat::i444)
    linesize[0] = w;
  return wrap_planes(format, size, data, linesize);
}

TEST(frame_planes, yuv_formats_give_back_what_they_were_given_within_one_step) {
  const cv::Size size(33, 17);  // odd: a last column and row of blocks of their own
  const cv::Mat bgr = blocky_picture(size);
  for (PixelFormat f : {PixelFormat::nv12, PixelFormat::i420, PixelFormat::yuy2, PixelFormat::uyvy,
                        PixelFormat::i444}) {
    std::vector<std::vector<std::uint8_t>> memory;
    std::vector<cv::Mat> planes = make_planes(f, size, memory);
    from_engine(bgr, f, bt709_limited(), planes);
    const cv::Mat back = to_engine(f, planes, bt709_limited(), size);
    ASSERT_EQ(back.type(), CV_8UC3);
    // Limited range codes 219 luma steps for 255 values: a colour comes back within 2.
    EXPECT_LE(cv::norm(back, bgr, cv::NORM_INF), 2) << static_cast<int>(f);
  }
}

TEST(frame_planes, limited_range_black_and_white_are_16_and_235) {
  const cv::Size size(4, 2);
  std::vector<std::vector<std::uint8_t>> memory;
  std::vector<cv::Mat> planes = make_planes(PixelFormat::nv12, size, memory);
  cv::Mat bgr(size, CV_8UC3, cv::Scalar::all(0));
  bgr(cv::Rect(2, 0, 2, 2)).setTo(cv::Scalar::all(255));
  from_engine(bgr, PixelFormat::nv12, bt709_limited(), planes);
  EXPECT_EQ(planes[0].at<std::uint8_t>(0, 0), 16);
  EXPECT_EQ(planes[0].at<std::uint8_t>(1, 3), 235);
  EXPECT_EQ(planes[1].at<cv::Vec2b>(0, 0), cv::Vec2b(128, 128));
  EXPECT_EQ(planes[1].at<cv::Vec2b>(0, 1), cv::Vec2b(128, 128));
}

TEST(frame_planes, rgba_reaches_the_engine_as_bgra_and_goes_back) {
  std::vector<std::vector<std::uint8_t>> memory;
  std::vector<cv::Mat> planes = make_planes(PixelFormat::rgba, {3, 2}, memory);
  planes[0].setTo(cv::Scalar(10, 20, 30, 40));  // R, G, B, A
  cv::Mat engine = to_engine(PixelFormat::rgba, planes, {}, {3, 2});
  EXPECT_EQ(engine.at<cv::Vec4b>(1, 2), cv::Vec4b(30, 20, 10, 40));
  engine.setTo(cv::Scalar(1, 2, 3, 4));  // B, G, R, A
  from_engine(engine, PixelFormat::rgba, {}, planes);
  EXPECT_EQ(planes[0].at<cv::Vec4b>(0, 0), cv::Vec4b(3, 2, 1, 4));
}

}  // namespace
}  // namespace ifsfx::obs
