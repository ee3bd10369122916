// SPDX-License-Identifier: Apache-2.0
#include "collage/target.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::collage {
namespace {

// A light image with a dark disc: what a silhouette on paper looks like.
cv::Mat dark_disc_on_light(int depth = CV_8U) {
  cv::Mat grey(60, 80, CV_8UC1, cv::Scalar(220));
  cv::circle(grey, {40, 30}, 15, cv::Scalar(30), cv::FILLED);
  cv::Mat bgr;
  cv::merge(std::vector<cv::Mat>{grey, grey, grey}, bgr);
  if (depth == CV_16U) bgr.convertTo(bgr, CV_16U, 257);
  if (depth == CV_32F) bgr.convertTo(bgr, CV_32F, 1.0 / 255);
  return bgr;
}

ErrorKind kind_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.kind();
  }
  ADD_FAILURE() << "no ifsfx::Error thrown";
  return ErrorKind::io;
}

TEST(target, otsu_takes_the_dark_shape_at_every_depth) {
  for (int depth : {CV_8U, CV_16U, CV_32F}) {
    const cv::Mat mask = shape_mask(dark_disc_on_light(depth));
    ASSERT_EQ(mask.type(), CV_8UC1);
    EXPECT_EQ(mask.at<std::uint8_t>(30, 40), 255) << "depth " << depth;
    EXPECT_EQ(mask.at<std::uint8_t>(2, 2), 0) << "depth " << depth;
    // A filled disc of radius 15 has ≈ π·15² pixels.
    EXPECT_NEAR(cv::countNonZero(mask), 3.14159 * 225, 40) << "depth " << depth;
  }
}

TEST(target, invert_takes_the_light_side) {
  const cv::Mat mask = shape_mask(dark_disc_on_light(), {.invert = true});
  EXPECT_EQ(mask.at<std::uint8_t>(30, 40), 0);
  EXPECT_EQ(mask.at<std::uint8_t>(2, 2), 255);
}

TEST(target, alpha_channel_is_the_shape_whatever_the_colour) {
  cv::Mat bgra(40, 40, CV_8UC4, cv::Scalar(0, 0, 0, 0));
  bgra(cv::Rect(10, 5, 20, 10)).setTo(cv::Scalar(255, 255, 255, 255));  // white but opaque
  const cv::Mat mask = shape_mask(bgra);
  EXPECT_EQ(cv::countNonZero(mask), 200);
  EXPECT_EQ(mask.at<std::uint8_t>(7, 12), 255);
}

TEST(target, explicit_threshold_is_a_fraction_of_full_scale) {
  cv::Mat grey(10, 10, CV_8UC1, cv::Scalar(200));
  grey(cv::Rect(0, 0, 5, 10)).setTo(100);  // 100/255 ≈ 0.39
  EXPECT_EQ(cv::countNonZero(shape_mask(grey, {.threshold = 0.5})), 50);
  EXPECT_EQ(cv::countNonZero(shape_mask(grey, {.threshold = 0.5, .invert = true})), 50);
}

TEST(target, empty_and_full_shapes_are_rejected) {
  const cv::Mat uniform(20, 20, CV_8UC1, cv::Scalar(128));
  EXPECT_EQ(kind_of([&] { shape_mask(uniform, {.threshold = 0.1}); }), ErrorKind::invalid_argument);
  EXPECT_EQ(kind_of([&] { shape_mask(uniform, {.threshold = 0.9}); }), ErrorKind::invalid_argument);
  cv::Mat clear(20, 20, CV_8UC4, cv::Scalar(0, 0, 0, 0));
  try {
    shape_mask(clear, {}, "clear.png");
    FAIL() << "an all-transparent image has no shape";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("clear.png: the shape is empty"), std::string::npos)
        << e.what();
  }
}

TEST(target, threshold_outside_the_unit_interval_is_rejected) {
  EXPECT_EQ(kind_of([&] { shape_mask(dark_disc_on_light(), {.threshold = 1.5}); }),
            ErrorKind::invalid_argument);
}

TEST(target, unreadable_file_is_an_error_naming_it) {
  try {
    load_target("/nonexistent/leaf.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/leaf.png"), std::string::npos) << e.what();
  }
}

TEST(target, working_raster_centres_the_shape_and_keeps_its_aspect) {
  // A 40×10 bar: framed in a square with 5% margins, it spans 90% of the width, 22.5% of height.
  cv::Mat mask(100, 200, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(30, 60, 40, 10)).setTo(255);
  const cv::Mat raster = working_raster(mask, {.size = 80, .margin = 0.05});
  ASSERT_EQ(raster.size(), cv::Size(80, 80));
  const cv::Rect box = cv::boundingRect(raster);
  EXPECT_NEAR(box.width, 72, 1);
  EXPECT_NEAR(box.height, 18, 1);
  EXPECT_NEAR(box.x + box.width / 2.0, 40, 1);
  EXPECT_NEAR(box.y + box.height / 2.0, 40, 1);
}

TEST(target, working_raster_size_is_checked) {
  cv::Mat mask(10, 10, CV_8UC1, cv::Scalar(0));
  mask.at<std::uint8_t>(5, 5) = 255;
  EXPECT_EQ(kind_of([&] { working_raster(mask, {.size = 4}); }), ErrorKind::invalid_argument);
}

}  // namespace
}  // namespace ifsfx::collage
