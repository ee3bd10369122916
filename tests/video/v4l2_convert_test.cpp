// SPDX-License-Identifier: Apache-2.0
// V4L2 buffer conversions against OpenCV's own YUV conversions (the reference) — including row
// padding (bytesperline > width), which OpenCV's calls never see.
#include "video/v4l2_convert.h"

#include <cstring>

#include <gtest/gtest.h>
#include <linux/videodev2.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::video {
namespace {

cv::Mat random_bytes(int rows, int cols, int type, unsigned seed) {
  cv::Mat m(rows, cols, type);
  cv::RNG rng(seed);
  rng.fill(m, cv::RNG::UNIFORM, 0, 256);
  return m;
}

// Copies `packed` rows into a buffer whose rows are `stride` bytes, padding filled with 0xAB.
std::vector<std::uint8_t> pad_rows(const cv::Mat& packed, std::size_t stride) {
  const std::size_t row = packed.cols * packed.elemSize();
  std::vector<std::uint8_t> out(stride * packed.rows, 0xAB);
  for (int y = 0; y < packed.rows; ++y) std::memcpy(out.data() + y * stride, packed.ptr(y), row);
  return out;
}

double max_diff(const cv::Mat& a, const cv::Mat& b) {
  return cv::norm(a, b, cv::NORM_INF);
}

TEST(v4l2_convert, yuyv_matches_opencv_with_padded_rows) {
  const cv::Mat yuyv = random_bytes(48, 64, CV_8UC2, 1);
  cv::Mat expected;
  cv::cvtColor(yuyv, expected, cv::COLOR_YUV2BGR_YUYV);
  const std::vector<std::uint8_t> buffer = pad_rows(yuyv, 64 * 2 + 32);
  const cv::Mat got = to_bgr(buffer, {PixelFormat::yuyv, {64, 48}, 64 * 2 + 32}, "/dev/video0");
  ASSERT_EQ(got.type(), CV_8UC3);
  EXPECT_EQ(max_diff(got, expected), 0);
}

TEST(v4l2_convert, uyvy_matches_opencv) {
  const cv::Mat uyvy = random_bytes(16, 32, CV_8UC2, 2);
  cv::Mat expected;
  cv::cvtColor(uyvy, expected, cv::COLOR_YUV2BGR_UYVY);
  const cv::Mat got = to_bgr({uyvy.data, uyvy.total() * 2}, {PixelFormat::uyvy, {32, 16}}, "cam");
  EXPECT_EQ(max_diff(got, expected), 0);
}

TEST(v4l2_convert, nv12_matches_opencv_with_padded_rows) {
  const cv::Mat nv12 = random_bytes(48 * 3 / 2, 64, CV_8UC1, 3);  // Y rows, then UV rows
  cv::Mat expected;
  cv::cvtColor(nv12, expected, cv::COLOR_YUV2BGR_NV12);
  const std::vector<std::uint8_t> buffer = pad_rows(nv12, 80);
  const cv::Mat got = to_bgr(buffer, {PixelFormat::nv12, {64, 48}, 80}, "cam");
  EXPECT_EQ(max_diff(got, expected), 0);
}

TEST(v4l2_convert, yuv420_matches_opencv_with_padded_rows) {
  const int w = 64, h = 48;
  const cv::Mat i420 = random_bytes(h * 3 / 2, w, CV_8UC1, 4);
  cv::Mat expected;
  cv::cvtColor(i420, expected, cv::COLOR_YUV2BGR_I420);
  // V4L2's single-plane YU12 with bytesperline s: Y rows of s bytes, then U and V planes whose
  // rows are s/2 bytes.
  const std::size_t s = 96;
  std::vector<std::uint8_t> buffer(s * h + 2 * (s / 2) * (h / 2), 0xAB);
  const std::uint8_t* src = i420.data;
  for (int y = 0; y < h; ++y) std::memcpy(buffer.data() + y * s, src + y * w, w);
  for (int plane = 0; plane < 2; ++plane) {
    const std::uint8_t* from = src + w * h + plane * (w / 2) * (h / 2);
    std::uint8_t* to = buffer.data() + s * h + plane * (s / 2) * (h / 2);
    for (int y = 0; y < h / 2; ++y) std::memcpy(to + y * (s / 2), from + y * (w / 2), w / 2);
  }
  const cv::Mat got = to_bgr(buffer, {PixelFormat::yuv420, {w, h}, s}, "cam");
  EXPECT_EQ(max_diff(got, expected), 0);
  const cv::Mat packed = to_bgr({i420.data, i420.total()}, {PixelFormat::yuv420, {w, h}}, "cam");
  EXPECT_EQ(max_diff(packed, expected), 0);
}

TEST(v4l2_convert, rgb24_is_swapped_to_bgr) {
  const cv::Mat rgb = random_bytes(8, 10, CV_8UC3, 5);
  cv::Mat expected;
  cv::cvtColor(rgb, expected, cv::COLOR_RGB2BGR);
  const cv::Mat got = to_bgr({rgb.data, rgb.total() * 3}, {PixelFormat::rgb24, {10, 8}}, "cam");
  EXPECT_EQ(max_diff(got, expected), 0);
}

TEST(v4l2_convert, mjpeg_decodes_like_imdecode) {
  cv::Mat image = random_bytes(32, 48, CV_8UC3, 6);
  cv::GaussianBlur(image, image, {5, 5}, 2);
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", image, jpeg));
  const cv::Mat expected = cv::imdecode(jpeg, cv::IMREAD_COLOR);
  const cv::Mat got = to_bgr(jpeg, {PixelFormat::mjpeg, {48, 32}}, "cam");
  EXPECT_EQ(max_diff(got, expected), 0);
}

TEST(v4l2_convert, corrupt_mjpeg_throws_io_naming_the_device) {
  std::vector<std::uint8_t> junk(1000, 0x42);
  try {
    to_bgr(junk, {PixelFormat::mjpeg, {48, 32}}, "/dev/video7");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_STREQ(e.what(), "/dev/video7: corrupt MJPEG frame (1000 bytes do not decode)");
  }
}

TEST(v4l2_convert, mjpeg_of_another_size_throws_io) {
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", cv::Mat(16, 16, CV_8UC3, cv::Scalar::all(90)), jpeg));
  EXPECT_THROW(to_bgr(jpeg, {PixelFormat::mjpeg, {48, 32}}, "cam"), Error);
}

TEST(v4l2_convert, short_buffer_throws_io_naming_the_device) {
  std::vector<std::uint8_t> data(100);
  try {
    to_bgr(data, {PixelFormat::yuyv, {64, 48}}, "/dev/video0");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_STREQ(e.what(), "/dev/video0: short YUYV frame: 64x48 needs 6144 bytes (got 100)");
  }
}

// A BGR image whose 2×2 blocks are one colour: then YUYV's pair chroma, OpenCV's 4:2:0 chroma and
// the pixel's own chroma all agree, so the Y, U and V samples can be compared one for one.
cv::Mat block_image(int w, int h, unsigned seed) {
  cv::Mat small = random_bytes(h / 2, w / 2, CV_8UC3, seed), image;
  cv::resize(small, image, {w, h}, 0, 0, cv::INTER_NEAREST);
  return image;
}

TEST(v4l2_convert, bgr_to_yuyv_matches_opencv_bt601_limited_range) {
  const int w = 64, h = 32;
  const cv::Mat bgr = block_image(w, h, 7);
  cv::Mat i420;
  cv::cvtColor(bgr, i420, cv::COLOR_BGR2YUV_I420);
  std::vector<std::uint8_t> yuyv;
  from_bgr(bgr, PixelFormat::yuyv, yuyv);
  ASSERT_EQ(yuyv.size(), static_cast<std::size_t>(w * h * 2));
  const std::uint8_t* Y = i420.data;
  const std::uint8_t* U = Y + w * h;
  const std::uint8_t* V = U + (w / 2) * (h / 2);
  int worst = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; x += 2) {
      const std::uint8_t* q = yuyv.data() + (y * w + x) * 2;
      const int c = (y / 2) * (w / 2) + x / 2;
      worst = std::max({worst, std::abs(q[0] - Y[y * w + x]), std::abs(q[2] - Y[y * w + x + 1]),
                        std::abs(q[1] - U[c]), std::abs(q[3] - V[c])});
    }
  }
  // Fixed-point rounding of two derivations of the same BT.601 coefficients.
  EXPECT_LE(worst, 1);
}

TEST(v4l2_convert, bgr_to_yuyv_round_trips_through_opencv) {
  const cv::Mat bgr = block_image(64, 32, 8);
  std::vector<std::uint8_t> yuyv;
  from_bgr(bgr, PixelFormat::yuyv, yuyv);
  cv::Mat back;
  cv::cvtColor(cv::Mat(32, 64, CV_8UC2, yuyv.data()), back, cv::COLOR_YUV2BGR_YUYV);
  // Limited range quantises Y in steps of 255/219 ≈ 1.16 and chroma in 255/224: a couple of
  // levels at most, never more.
  EXPECT_LE(max_diff(back, bgr), 3);
}

TEST(v4l2_convert, bgr_to_yuyv_averages_the_chroma_of_a_pair) {
  cv::Mat bgr(1, 2, CV_8UC3);
  bgr.at<cv::Vec3b>(0, 0) = {255, 0, 0};  // blue
  bgr.at<cv::Vec3b>(0, 1) = {0, 0, 255};  // red
  std::vector<std::uint8_t> yuyv;
  from_bgr(bgr, PixelFormat::yuyv, yuyv);
  cv::Mat purple(1, 2, CV_8UC3, cv::Scalar(128, 0, 128));
  // The pair's chroma is that of the mean colour (U and V are linear in R, G, B).
  std::vector<std::uint8_t> mean_yuyv;
  from_bgr(purple, PixelFormat::yuyv, mean_yuyv);
  EXPECT_NEAR(yuyv[1], mean_yuyv[1], 1);
  EXPECT_NEAR(yuyv[3], mean_yuyv[3], 1);
  EXPECT_EQ(yuyv[0], 41);  // Y of pure blue: 16 + 24.966 = 40.97
  EXPECT_EQ(yuyv[2], 81);  // Y of pure red: 16 + 65.481 = 81.48
}

TEST(v4l2_convert, bgr_to_yuv420_matches_opencv) {
  const cv::Mat bgr = random_bytes(32, 64, CV_8UC3, 9);
  cv::Mat expected;
  cv::cvtColor(bgr, expected, cv::COLOR_BGR2YUV_I420);
  std::vector<std::uint8_t> out;
  from_bgr(bgr, PixelFormat::yuv420, out);
  ASSERT_EQ(out.size(), expected.total());
  EXPECT_EQ(std::memcmp(out.data(), expected.data, out.size()), 0);
}

TEST(v4l2_convert, yuv420_output_rejects_odd_sizes) {
  std::vector<std::uint8_t> out;
  EXPECT_THROW(from_bgr(cv::Mat(3, 4, CV_8UC3), PixelFormat::yuv420, out), Error);
  EXPECT_THROW(from_bgr(cv::Mat(4, 4, CV_8UC1), PixelFormat::yuyv, out), Error);
}

TEST(v4l2_convert, fourcc_names_and_parsing_agree) {
  EXPECT_EQ(fourcc(PixelFormat::yuyv), V4L2_PIX_FMT_YUYV);
  EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_MJPEG), "MJPG");
  EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_YUV420), "YU12");
  EXPECT_EQ(pixel_format_from_fourcc(V4L2_PIX_FMT_NV12), PixelFormat::nv12);
  EXPECT_EQ(pixel_format_from_fourcc(V4L2_PIX_FMT_JPEG), PixelFormat::mjpeg);
  EXPECT_FALSE(pixel_format_from_fourcc(V4L2_PIX_FMT_H264).has_value());
  EXPECT_EQ(parse_pixel_format("MJPG"), PixelFormat::mjpeg);
  EXPECT_EQ(parse_pixel_format("i420"), PixelFormat::yuv420);
  try {
    parse_pixel_format("h264");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
  }
}

}  // namespace
}  // namespace ifsfx::video
