// SPDX-License-Identifier: Apache-2.0
#include "collage/distance.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::collage {
namespace {

cv::Mat points(std::initializer_list<cv::Point> where, int size = 32) {
  cv::Mat m(size, size, CV_8UC1, cv::Scalar(0));
  for (const auto& p : where) m.at<std::uint8_t>(p) = 255;
  return m;
}

TEST(distance, transform_is_exact_euclidean) {
  const cv::Mat d = distance_to(points({{3, 4}}));
  EXPECT_FLOAT_EQ(d.at<float>(4, 3), 0);
  EXPECT_NEAR(d.at<float>(4 + 12, 3 + 5), 13, 1e-4);  // a 5-12-13 triangle
  EXPECT_NEAR(d.at<float>(4 + 7, 3 + 7), 7 * std::sqrt(2.0), 1e-4);
}

TEST(distance, hausdorff_of_two_points_is_their_distance) {
  EXPECT_NEAR(hausdorff(points({{1, 1}}), points({{4, 5}})), 5, 1e-5);
}

TEST(distance, hausdorff_is_the_larger_directed_distance) {
  // a = {(0,0)}, b = {(0,0), (10,0)}: every point of a is in b, but (10,0) is 10 from a.
  const cv::Mat a = points({{0, 0}}), b = points({{0, 0}, {10, 0}});
  EXPECT_NEAR(directed_hausdorff(a, b), 0, 1e-6);
  EXPECT_NEAR(directed_hausdorff(b, a), 10, 1e-5);
  EXPECT_NEAR(hausdorff(a, b), 10, 1e-5);
}

TEST(distance, chamfer_averages_both_ways) {
  const cv::Mat a = points({{0, 0}}), b = points({{0, 0}, {10, 0}});
  // mean over a of d(·, b) = 0; mean over b of d(·, a) = (0 + 10) / 2 = 5.
  EXPECT_NEAR(chamfer(a, b), 2.5, 1e-5);
}

TEST(distance, iou_counts_pixels) {
  cv::Mat a(10, 10, CV_8UC1, cv::Scalar(0)), b = a.clone();
  a(cv::Rect(0, 0, 6, 10)).setTo(255);  // 60 pixels
  b(cv::Rect(3, 0, 7, 10)).setTo(255);  // 70 pixels, 30 shared
  EXPECT_DOUBLE_EQ(iou(a, b), 30.0 / 100.0);
}

TEST(distance, empty_mask_is_an_error) {
  EXPECT_THROW(distance_to(points({})), Error);
  EXPECT_THROW(hausdorff(points({}), points({{1, 1}})), Error);
}

}  // namespace
}  // namespace ifsfx::collage
