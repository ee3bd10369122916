#include "collage/initialise.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "collage/distance.h"
#include "ifs/error.h"

namespace ifsfx::collage {
namespace {

cv::Mat framed_square() {
  cv::Mat square(64, 64, CV_8UC1, cv::Scalar(0));
  square(cv::Rect(8, 8, 48, 48)).setTo(255);
  return square;
}

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

TEST(initialise, map_count_is_checked) {
  EXPECT_THROW(initial_maps(framed_square(), 0), Error);
  cv::Mat tiny(16, 16, CV_8UC1, cv::Scalar(0));
  tiny(cv::Rect(2, 2, 2, 2)).setTo(255);
  EXPECT_THROW(initial_maps(tiny, 5), Error) << "more maps than pixels";
}

}  // namespace
}  // namespace ifsfx::collage
