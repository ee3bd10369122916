// SPDX-License-Identifier: Apache-2.0
// GIF's palette pictures (engine/palette.h): a picture of no more than 256 colours keeps them
// exactly; a photograph-like one gets 256 entries close to its colours, its frequent flat colour
// kept exactly, and the same picture always gives the same bytes.
#include "engine/palette.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "same_bytes.h"

namespace ifsfx::engine {
namespace {

using ifsfx::testing::same_bytes;

cv::Mat rebuilt(const IndexedImage& indexed) {
  cv::Mat out(indexed.indices.size(), CV_8UC3);
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c)
      out.at<cv::Vec3b>(r, c) = indexed.palette.at(indexed.indices.at<std::uint8_t>(r, c));
  return out;
}

// A smooth colour field of 96·96 distinct colours on a black background.
cv::Mat gradient_on_black() {
  cv::Mat image(128, 128, CV_8UC3, cv::Scalar::all(0));
  for (int r = 16; r < 112; ++r)
    for (int c = 16; c < 112; ++c)
      image.at<cv::Vec3b>(r, c) = {static_cast<uchar>(c * 2), static_cast<uchar>(r * 2),
                                   static_cast<uchar>(255 - c - r / 2)};
  return image;
}

TEST(palette, a_picture_of_256_colours_or_fewer_keeps_them_exactly) {
  cv::Mat image(40, 64, CV_8UC3);
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c)
      image.at<cv::Vec3b>(r, c) = {static_cast<uchar>(c * 4), static_cast<uchar>(r % 4 * 60), 7};
  const IndexedImage indexed = to_indexed(image);  // 64 × 4 = 256 colours
  EXPECT_TRUE(indexed.exact);
  EXPECT_EQ(indexed.palette.size(), 256u);
  EXPECT_TRUE(same_bytes(rebuilt(indexed), image));
}

TEST(palette, many_colours_get_256_close_entries_and_the_background_stays_exact) {
  const cv::Mat image = gradient_on_black();
  const IndexedImage indexed = to_indexed(image);
  EXPECT_FALSE(indexed.exact);
  EXPECT_EQ(indexed.palette.size(), 256u);
  const cv::Mat back = rebuilt(indexed);
  EXPECT_GT(cv::PSNR(back, image), 30.0);
  // The black border (over 40% of the picture) is black, undithered.
  cv::Mat border = back(cv::Rect(0, 0, 128, 16));
  EXPECT_EQ(cv::countNonZero(border.reshape(1)), 0);
  // The same picture, the same bytes.
  const IndexedImage again = to_indexed(image);
  EXPECT_TRUE(same_bytes(again.indices, indexed.indices));
  EXPECT_EQ(again.palette, indexed.palette);
}

TEST(palette, ordered_dithering_stays_put_where_the_picture_does) {
  // Two pictures differing in one corner: the rest keeps its indices (no error diffusion that
  // would carry the change across the frame and make an animation crawl).
  cv::Mat a = gradient_on_black(), b = a.clone();
  cv::rectangle(b, {100, 100, 20, 20}, cv::Scalar(40, 200, 90), -1);
  const IndexedImage ia = to_indexed(a), ib = to_indexed(b);
  const cv::Rect far(16, 16, 40, 40);
  cv::Mat ca = rebuilt(ia)(far), cb = rebuilt(ib)(far);
  EXPECT_LT(cv::norm(ca, cb, cv::NORM_L1) / static_cast<double>(far.area() * 3), 2.0);
}

TEST(palette, a_picture_that_is_not_8_bit_bgr_is_refused) {
  try {
    (void)to_indexed(cv::Mat(4, 4, CV_8UC1, cv::Scalar(0)));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "palette: needs a non-empty 8-bit BGR image (got 4x4, type 0)");
  }
}

}  // namespace
}  // namespace ifsfx::engine
