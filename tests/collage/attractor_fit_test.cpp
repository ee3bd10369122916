// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_fit.h"

#include <gtest/gtest.h>

#include "collage/reseed.h"
#include "ifs/error.h"

#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

TEST(attractor_fit, cmaes_on_the_attractor_puts_moved_quadrants_back) {
  // The quadrant maps moved and turned: their attractor misses much of the square.
  auto start = testing::quadrant_maps();
  Rng rng(3);
  start = perturbed(start, {0.5, 0.5}, 0.97, 0.3, rng);
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  const double before = loss.terms(start).iou;
  ASSERT_LT(before, 0.85);
  const AttractorRefined r =
      refine_on_attractor(loss, start, {.centre = {0.5, 0.5}, .max_evaluations = 3000});
  EXPECT_GE(loss.terms(r.maps).iou, 0.93) << "from " << before;
  EXPECT_EQ(r.value, loss(r.maps));
  for (const AffineMap& f : r.maps) EXPECT_LT(f.contraction(), 0.97);
}

TEST(attractor_fit, the_same_seed_gives_the_same_maps_for_any_thread_count) {
  auto start = testing::quadrant_maps();
  start[1].e += 0.05;
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  AttractorRefineOptions o{.centre = {0.5, 0.5}, .max_evaluations = 300, .seed = 9};
  o.threads = 1;
  const auto one = refine_on_attractor(loss, start, o);
  o.threads = 3;
  const auto three = refine_on_attractor(loss, start, o);
  EXPECT_EQ(one.maps, three.maps);
  EXPECT_EQ(one.evaluations, three.evaluations);
}

TEST(attractor_fit, perturbation_moves_every_map_and_keeps_reflections) {
  std::vector<AffineMap> maps = testing::quadrant_maps();
  maps[2].a = -maps[2].a;  // a reflected map
  Rng rng(1);
  const auto moved = perturbed(maps, {0.5, 0.5}, 0.97, 0.1, rng);
  for (std::size_t n = 0; n < maps.size(); ++n) {
    EXPECT_NE(moved[n], maps[n]);
    EXPECT_EQ(moved[n].det() < 0, maps[n].det() < 0) << n;
  }
}

TEST(attractor_fit, metropolis_takes_gains_always_and_losses_by_their_odds) {
  EXPECT_TRUE(metropolis_accepts(-0.1, 0, 0.99));
  EXPECT_TRUE(metropolis_accepts(0.01, 0.01, 0.3));   // exp(−1) ≈ 0.37 > 0.3
  EXPECT_FALSE(metropolis_accepts(0.01, 0.01, 0.4));  // … < 0.4
  EXPECT_FALSE(metropolis_accepts(0.01, 0, 0));       // no temperature, no loss taken
}

TEST(attractor_fit, reseed_puts_the_map_that_pays_least_on_the_part_a_misses) {
  // L is a disc and a square apart; A is the five-petalled flower shrunk into the disc, one of
  // its maps twice: A misses the square, and either copy of the twice-given map is worth nothing.
  const cv::Mat shape = testing::disc_and_square(96);
  std::vector<AffineMap> maps = testing::flower_in_disc();
  maps.push_back(maps[1]);
  const AttractorLoss judge(shape, {.size = 96, .keep = 0});
  const ErrorMaps errors = error_maps(judge.target(), judge.raster(maps), 4);
  ASSERT_FALSE(errors.missed_regions.empty());
  const cv::Mat& missed = errors.missed_regions.front().mask;
  const cv::Rect square(57, 32, 32, 32);
  EXPECT_EQ(cv::countNonZero(missed(square)), 32 * 32);
  EXPECT_EQ(errors.missed_regions.front().area, 32 * 32);  // nothing of the disc with it
  const std::vector<int> order = least_paying(judge, maps);
  ASSERT_EQ(order.size(), maps.size());
  const int weakest = order.front();
  EXPECT_TRUE(weakest == 1 || weakest == 5) << weakest;
  const std::vector<AffineMap> found = maps_onto_region(shape, missed);
  ASSERT_FALSE(found.empty());
  const AffineMap& placed = found.front();
  // The search sends L's centroid to the piece's: the square's centre.
  const cv::Moments m = cv::moments(shape, true);
  const Point at = placed({(m.m10 / m.m00 + 0.5) / 96, 1 - (m.m01 / m.m00 + 0.5) / 96});
  EXPECT_NEAR(at.x, 73.0 / 96, 0.02);
  EXPECT_NEAR(at.y, 1 - 48.0 / 96, 0.02);
  const double before = judge.terms(maps).iou;
  maps[static_cast<std::size_t>(weakest)] = placed;
  // A gains a copy of itself on the square (0.375 -> 0.543).
  EXPECT_GT(judge.terms(maps).iou, before + 0.1) << "from " << before;
}

TEST(attractor_fit, error_maps_tell_missed_from_spilled_and_drop_one_pixel_slivers) {
  cv::Mat target(32, 32, CV_8UC1, cv::Scalar(0)), attractor(32, 32, CV_8UC1, cv::Scalar(0));
  target(cv::Rect(4, 4, 20, 20)).setTo(255);
  attractor(cv::Rect(4, 4, 10, 19)).setTo(255);  // a 1-pixel sliver of L left at the bottom
  attractor(cv::Rect(26, 4, 4, 4)).setTo(255);   // a spill right of L
  const ErrorMaps e = error_maps(target, attractor);
  ASSERT_EQ(e.missed_regions.size(), 1u);
  EXPECT_EQ(e.missed_regions[0].area, 10 * 20);  // the right half, without the sliver
  ASSERT_EQ(e.spilled_regions.size(), 1u);
  EXPECT_EQ(e.spilled_regions[0].area, 16);
  EXPECT_THROW(error_maps(target, attractor(cv::Rect(0, 0, 16, 16))), Error);
}

}  // namespace
}  // namespace ifsfx::collage
