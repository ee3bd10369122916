// SPDX-License-Identifier: Apache-2.0
#include "collage/grow.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "collage/fit.h"
#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

constexpr int kSize = 96;

// L's centroid (plane units), where every searched map of L onto a piece sends it to the piece's.
Point centroid(const cv::Mat& shape) {
  const cv::Moments m = cv::moments(shape, true);
  return {(m.m10 / m.m00 + 0.5) / shape.cols, 1 - (m.m01 / m.m00 + 0.5) / shape.rows};
}

// Whether some map sends L's centroid into the square of disc_and_square (57..89 px across,
// 32..64 px down).
bool some_map_on_the_square(const std::vector<AffineMap>& maps, const cv::Mat& shape) {
  for (const AffineMap& f : maps) {
    const Point at = f(centroid(shape));
    const double x = at.x * kSize, y = (1 - at.y) * kSize;
    if (x > 57 && x < 89 && y > 32 && y < 64) return true;
  }
  return false;
}

TEST(grow, the_added_map_goes_onto_the_piece_a_misses) {
  const cv::Mat shape = testing::disc_and_square(kSize);
  const AttractorLoss judge(shape, {.size = kSize, .keep = 0});
  const std::vector<AffineMap> flower = testing::flower_in_disc();
  ASSERT_FALSE(some_map_on_the_square(flower, shape));
  const auto grown = with_map_where_missed(judge, shape, flower, flower.front());
  ASSERT_EQ(grown.size(), flower.size() + 1);
  EXPECT_TRUE(std::equal(flower.begin(), flower.end(), grown.begin()));  // the others kept
  EXPECT_TRUE(some_map_on_the_square(grown, shape));
  // A gains a copy of itself on the square (0.375 -> 0.54 measured).
  EXPECT_GT(judge.terms(grown).iou, judge.terms(flower).iou + 0.1);
}

TEST(grow, a_set_that_misses_a_piece_grows_a_map_onto_it_and_keeps_its_size) {
  // Two components, N = 6: the flower's five maps in the disc and one of them twice. Dropping the
  // two that pay least leaves a flower that misses the square; growing puts a map on it.
  const cv::Mat shape = testing::disc_and_square(kSize);
  const AttractorLoss judge(shape, {.size = kSize, .keep = 0});
  std::vector<AffineMap> from = testing::flower_in_disc();
  from.push_back(from[1]);
  std::vector<std::size_t> sizes;
  std::vector<int> steps, counts;
  int renderings = 0, searches = 0;
  GrowOptions o;
  o.reoptimise = [&](std::vector<AffineMap> maps, int step, int count) {
    sizes.push_back(maps.size());
    steps.push_back(step);
    counts.push_back(count);
    return maps;
  };
  o.charge = [&](int r, int s) {
    renderings += r;
    searches += s;
  };
  const std::vector<AffineMap> grown = grow_maps(judge, shape, from, o);
  ASSERT_EQ(grown.size(), from.size());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{4, 5, 6}));
  EXPECT_EQ(steps, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(counts, (std::vector<int>{3, 3, 3}));
  EXPECT_TRUE(some_map_on_the_square(grown, shape));
  EXPECT_GE(judge.terms(grown).iou, 0.5) << "from " << judge.terms(from).iou;
  EXPECT_GT(renderings, 6);  // the least-paying order and the screened sets
  EXPECT_GE(searches, 1);
  // The same inputs, the same maps.
  EXPECT_EQ(grow_maps(judge, shape, from, o), grown);
}

TEST(grow, where_a_misses_nothing_the_dropped_maps_come_back) {
  // No missed region is large enough for a map (none is twice the size of L): each step adds a
  // spare back.
  const cv::Mat square = testing::framed_square();
  const AttractorLoss judge(square, {.size = 64, .keep = 0});
  const std::vector<AffineMap> quadrants = testing::quadrant_maps();
  const std::vector<AffineMap> grown = grow_maps(judge, square, quadrants, {.min_region = 2});
  ASSERT_EQ(grown.size(), quadrants.size());
  for (const AffineMap& f : quadrants)
    EXPECT_NE(std::find(grown.begin(), grown.end(), f), grown.end());
  // One map: nothing to drop, the set as it was.
  EXPECT_EQ(grow_maps(judge, square, std::vector<AffineMap>{quadrants[0]}),
            std::vector<AffineMap>{quadrants[0]});
}

// A small fit that its evaluations end (the same on any machine), growing on a twentieth of the
// attractor's stages.
FitOptions quick_growing(int maps) {
  FitOptions o = testing::quick(maps);
  o.grow_share = 0.05;
  return o;
}

TEST(grow, a_growing_fit_gives_the_same_maps_for_any_thread_count) {
  const cv::Mat shape = testing::disc_and_square(64);
  FitOptions o = quick_growing(4);
  o.threads = 1;
  const FitResult one = fit(shape, o);
  o.threads = 2;
  const FitResult two = fit(shape, o);
  ASSERT_EQ(one.ifs.maps.size(), 4u);
  EXPECT_EQ(one.ifs.maps, two.ifs.maps);
  EXPECT_EQ(one.evaluations, two.evaluations);
  o.grow_share = 0;
  const FitResult without = fit(shape, o);
  // The share reaches the stages (0.817 with it, 0.823 without, measured).
  EXPECT_NE(one.ifs.maps, without.ifs.maps);
  EXPECT_GE(one.report.iou, 0.8);
}

}  // namespace
}  // namespace ifsfx::collage
