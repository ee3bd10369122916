// SPDX-License-Identifier: Apache-2.0
#include "collage/initialise.h"

#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "collage/distance.h"
#include "ifs/error.h"
#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

using testing::framed_square;

TEST(initialise, principal_axes_split_a_square_into_its_quadrants) {
  const cv::Mat labels = partition(framed_square(), 4);
  // Each quadrant of the square is one part.
  for (const cv::Rect q : {cv::Rect(8, 8, 24, 24), cv::Rect(32, 8, 24, 24), cv::Rect(8, 32, 24, 24),
                           cv::Rect(32, 32, 24, 24)}) {
    const int first = labels.at<int>(q.y, q.x);
    EXPECT_GE(first, 0);
    cv::Mat same = labels(q) == first;
    EXPECT_EQ(cv::countNonZero(same), q.area());
  }
  EXPECT_EQ(labels.at<int>(0, 0), -1) << "outside L";
}

TEST(initialise, moment_matched_maps_of_a_square_are_its_quadrant_maps) {
  const cv::Mat square = framed_square();
  const auto maps = initial_maps(square, 4);
  ASSERT_EQ(maps.size(), 4u);
  for (const auto& f : maps) {
    EXPECT_NEAR(f.contraction(), 0.5, 0.01);
    EXPECT_NEAR(std::abs(f.det()), 0.25, 0.01);
  }
  EXPECT_GE(iou(collage_raster(square, maps), square), 0.95);
}

TEST(initialise, is_deterministic_and_seeds_vary_the_restarts) {
  cv::Mat blob(64, 64, CV_8UC1, cv::Scalar(0));
  cv::ellipse(blob, {30, 34}, {25, 12}, 20, 0, 360, cv::Scalar(255), cv::FILLED);
  EXPECT_EQ(initial_maps(blob, 3), initial_maps(blob, 3));
  const InitOptions a{.split = Split::kmeans_plus_plus, .seed = 1};
  const InitOptions b{.split = Split::kmeans_plus_plus, .seed = 2};
  EXPECT_EQ(initial_maps(blob, 3, a), initial_maps(blob, 3, a));
  EXPECT_NE(initial_maps(blob, 3, a), initial_maps(blob, 3, b));
}

TEST(initialise, single_map_is_shrunk_to_a_contraction) {
  const auto maps = initial_maps(framed_square(), 1);
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_LT(maps[0].contraction(), 0.95);
}

// A large square on the left and a small one on the right, apart.
cv::Mat two_squares() {
  cv::Mat m(64, 64, CV_8UC1, cv::Scalar(0));
  m(cv::Rect(4, 8, 36, 36)).setTo(255);
  m(cv::Rect(46, 20, 14, 14)).setTo(255);
  return m;
}

// The labels present in `labels` under `mask`.
std::set<int> labels_in(const cv::Mat& labels, const cv::Mat& mask) {
  std::set<int> out;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (mask.at<std::uint8_t>(r, c)) out.insert(labels.at<int>(r, c));
  return out;
}

TEST(initialise, by_component_gives_each_component_its_own_parts) {
  const cv::Mat l = two_squares();
  const cv::Mat big = l.clone(), small = l.clone();
  big(cv::Rect(44, 0, 20, 64)).setTo(0);
  small(cv::Rect(0, 0, 44, 64)).setTo(0);
  for (const Split split : {Split::principal_axes, Split::kmeans_plus_plus}) {
    const cv::Mat labels = partition(l, 3, {.split = split, .by_component = true});
    const auto in_big = labels_in(labels, big), in_small = labels_in(labels, small);
    EXPECT_EQ(in_big.size(), 2u) << "the larger area gets the spare part";
    EXPECT_EQ(in_small.size(), 1u);
    for (int k : in_small) EXPECT_EQ(in_big.count(k), 0u) << "a part straddles the gap";
  }
  // Without it, the pixels are split as one set: a part straddles the gap.
  const cv::Mat plain = partition(l, 2);
  const auto small_plain = labels_in(plain, small);
  ASSERT_EQ(small_plain.size(), 1u);
  EXPECT_EQ(labels_in(plain, big).count(*small_plain.begin()), 1u);
}

TEST(initialise, component_too_small_for_a_part_joins_the_nearest_part) {
  cv::Mat l = framed_square();
  l(cv::Rect(58, 30, 2, 2)).setTo(255);  // 4 pixels beside a square of 2304
  const cv::Mat labels = partition(l, 4, {.by_component = true});
  cv::Mat dot(64, 64, CV_8UC1, cv::Scalar(0));
  dot(cv::Rect(58, 30, 2, 2)).setTo(255);
  const auto in_dot = labels_in(labels, dot);
  ASSERT_EQ(in_dot.size(), 1u);
  EXPECT_EQ(labels_in(labels, framed_square()).size(), 4u) << "all four parts on the square";
  const int k = *in_dot.begin();
  EXPECT_GE(k, 0);
  // The part it joins is one on the square's right half (the dot sits to the right).
  cv::Mat part = labels == k;
  part(cv::Rect(56, 0, 8, 64)).setTo(0);
  EXPECT_GT(cv::boundingRect(part).x, 20);
}

TEST(initialise, map_count_is_checked) {
  EXPECT_THROW(initial_maps(framed_square(), 0), Error);
  cv::Mat tiny(16, 16, CV_8UC1, cv::Scalar(0));
  tiny(cv::Rect(2, 2, 2, 2)).setTo(255);
  EXPECT_THROW(initial_maps(tiny, 5), Error) << "more maps than pixels";
}

}  // namespace
}  // namespace ifsfx::collage
