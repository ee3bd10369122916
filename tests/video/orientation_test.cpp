// SPDX-License-Identifier: Apache-2.0
#include "video/orientation.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "ifs/error.h"
#include "tests/video/test_frames.h"

namespace ifsfx::video {
namespace {

constexpr std::int32_t kOne = 1 << 16;  // 1.0 in the matrix's 16.16 fixed point
constexpr std::int32_t kW = 1 << 30;    // 1.0 in 2.30, the last entry

// {a b u; c d v; x y w} with the translation left at 0 (it only places the picture).
void matrix(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t d, std::int32_t out[9]) {
  const std::int32_t m[9] = {a * kOne, b * kOne, 0, c * kOne, d * kOne, 0, 0, 0, kW};
  std::copy(m, m + 9, out);
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// A picture that no turn or mirror maps onto itself: a gradient, a marker, a rectangle not square.
cv::Mat asymmetric() {
  return testing::test_frame({24, 16}, 3);
}

TEST(orientation, phone_portrait_matrix_turns_clockwise) {
  // An upright phone's clip: the sensor's landscape picture, tkhd matrix {0 1; -1 0}.
  std::int32_t m[9];
  matrix(0, 1, -1, 0, m);
  const Orientation o = orientation_from_matrix(m, "clip.mp4");
  EXPECT_EQ(o.describe(), "turned 90° clockwise");
  const cv::Mat in = asymmetric();
  cv::Mat want;
  cv::rotate(in, want, cv::ROTATE_90_CLOCKWISE);
  EXPECT_TRUE(same(o.apply(in), want));
  EXPECT_EQ(o.displayed({24, 16}), cv::Size(16, 24));
}

TEST(orientation, half_and_three_quarter_turns_and_mirrors) {
  const cv::Mat in = asymmetric();
  std::int32_t m[9];
  cv::Mat want;

  matrix(-1, 0, 0, -1, m);
  cv::rotate(in, want, cv::ROTATE_180);
  EXPECT_TRUE(same(orientation_from_matrix(m, "x").apply(in), want));
  EXPECT_EQ(orientation_from_matrix(m, "x").describe(), "turned 180°");

  matrix(0, -1, 1, 0, m);
  cv::rotate(in, want, cv::ROTATE_90_COUNTERCLOCKWISE);
  EXPECT_TRUE(same(orientation_from_matrix(m, "x").apply(in), want));
  EXPECT_EQ(orientation_from_matrix(m, "x").describe(), "turned 90° counterclockwise");

  matrix(-1, 0, 0, 1, m);  // a front camera's mirror
  cv::flip(in, want, 1);
  EXPECT_TRUE(same(orientation_from_matrix(m, "x").apply(in), want));

  matrix(1, 0, 0, 1, m);
  EXPECT_TRUE(orientation_from_matrix(m, "x").identity());
  EXPECT_TRUE(same(orientation_from_matrix(m, "x").apply(in), in));
}

TEST(orientation, scaled_matrix_is_read_by_its_signs) {
  std::int32_t m[9];
  matrix(0, 2, -2, 0, m);
  EXPECT_EQ(orientation_from_matrix(m, "x").describe(), "turned 90° clockwise");
}

TEST(orientation, turn_that_is_not_a_quarter_is_refused_by_name) {
  // 30° clockwise: cos 30° = 0.866, sin 30° = 0.5 (b = sin, c = -sin as for the phone's 90°).
  const std::int32_t m[9] = {56756, 32768, 0, -32768, 56756, 0, 0, 0, kW};
  try {
    orientation_from_matrix(m, "clip.mp4");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_STREQ(e.what(),
                 "clip.mp4: the video is to be shown turned by 30.0° clockwise; only multiples of "
                 "90° are supported");
  }
}

TEST(orientation, rotate_tag_turns_clockwise_like_the_phone_matrix) {
  std::int32_t phone[9];
  matrix(0, 1, -1, 0, phone);
  const Orientation tagged = orientation_from_rotate_tag("90", "clip.mkv");
  const Orientation from_matrix = orientation_from_matrix(phone, "clip.mkv");
  EXPECT_EQ(tagged.transpose, from_matrix.transpose);
  EXPECT_EQ(tagged.flip_x, from_matrix.flip_x);
  EXPECT_EQ(tagged.flip_y, from_matrix.flip_y);
  EXPECT_EQ(orientation_from_rotate_tag("180", "x").describe(), "turned 180°");
  EXPECT_EQ(orientation_from_rotate_tag("270", "x").describe(), "turned 90° counterclockwise");
  EXPECT_EQ(orientation_from_rotate_tag("-90", "x").describe(), "turned 90° counterclockwise");
  EXPECT_TRUE(orientation_from_rotate_tag("0", "x").identity());
  EXPECT_TRUE(orientation_from_rotate_tag("360", "x").identity());
  for (const char* bad : {"45", "abc", "", "90deg"}) {
    try {
      orientation_from_rotate_tag(bad, "clip.mkv");
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::unsupported);
      EXPECT_EQ(std::string(e.what()),
                std::string("clip.mkv: rotate tag: only multiples of 90° are supported (got '") +
                    bad + "')");
    }
  }
}

}  // namespace
}  // namespace ifsfx::video
