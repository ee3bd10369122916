// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_loss.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "ifs/cpu.h"

#include "ifs/error.h"
#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

TEST(attractor_loss, a_tiling_scores_its_own_square_at_every_level) {
  // The quadrant maps' attractor is the framed square itself.
  for (int size : {32, 64}) {
    const AttractorLoss loss(testing::framed_square(), {.size = size});
    const AttractorTerms t = loss.terms(testing::quadrant_maps());
    EXPECT_GE(t.iou, 0.97) << size;
    EXPECT_LT(t.spill, 0.5 / size) << "the points stay within half a pixel of L";
    EXPECT_LT(t.coverage, 0.5 / size) << "every pixel of L is hit or next to a hit";
    EXPECT_EQ(loss.target().cols, size);
  }
}

TEST(attractor_loss, a_moved_map_costs_more_the_further_it_moves) {
  const AttractorLoss loss(testing::framed_square(), {.size = 64});
  double last = loss(testing::quadrant_maps());
  for (double shift : {0.02, 0.05, 0.1}) {
    auto maps = testing::quadrant_maps();
    maps[3].e += shift;
    maps[3].f += shift;
    const double value = loss(maps);
    EXPECT_GT(value, last) << "shift " << shift;
    last = value;
  }
}

TEST(attractor_loss, the_same_maps_get_the_same_value_every_time) {
  // Common random numbers: the draws are fixed when the loss is built.
  const AttractorLoss loss(testing::framed_square(), {.size = 32, .seed = 5});
  auto maps = testing::quadrant_maps();
  maps[0].a = 0.3;
  EXPECT_EQ(loss(maps), loss(maps));
  const AttractorLoss again(testing::framed_square(), {.size = 32, .seed = 5});
  EXPECT_EQ(again(maps), loss(maps));
}

TEST(attractor_loss, spill_and_coverage_are_plane_distances) {
  // One map that shrinks the plane to almost a point at (0.95, 0.95), outside the square
  // [1/8, 7/8]²: L's nearest pixel centre is (55.5/64, 55.5/64), so the points spill
  // (0.95 − 0.867)·√2 ≈ 0.117 away from L; and L's pixels lie on average far from that point.
  const AttractorLoss loss(testing::framed_square(), {.size = 64});
  const std::vector<AffineMap> maps = {{0.001, 0, 0, 0.001, 0.95, 0.95}};
  const AttractorTerms t = loss.terms(maps);
  EXPECT_EQ(t.iou, 0);
  EXPECT_NEAR(t.spill, 0.117, 0.003);
  EXPECT_GT(t.coverage, 0.3);
  EXPECT_LT(t.coverage, 0.7);
}

TEST(attractor_loss, coverage_is_the_mean_chamfer_distance_of_l_from_a) {
  // A is the left half of L (four maps of the half onto its quarters): on 32², L is 24×24
  // pixels and each row's 12 right-hand pixels lie 1..12 horizontal steps of the 3×3 chamfer
  // distance (0.955 pixel) from A, so the mean over L is 0.955 · 78 / 24 pixels, 0.0970 plane
  // units.
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  std::vector<AffineMap> half;
  for (double y : {0.125, 0.5})
    for (double x : {0.125, 0.3125})
      half.push_back(rectangle_map(0.125, 0.125, 0.5, 0.875, x, y, x + 0.1875, y + 0.375));
  EXPECT_NEAR(loss.terms(half).coverage, 0.955 * 78 / 24 / 32, 0.002);
}

TEST(attractor_loss, the_raster_is_what_the_points_hit) {
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  const cv::Mat a = loss.raster(testing::quadrant_maps());
  EXPECT_EQ(a.size(), cv::Size(32, 32));
  EXPECT_GE(cv::countNonZero(a & loss.target()), 0.97 * cv::countNonZero(loss.target()));
}

TEST(attractor_loss, a_thin_part_is_kept_at_any_cover_and_dropped_at_half) {
  // A line one pixel wide on 128² covers a quarter of each pixel it crosses on 32²: half cover
  // drops it (the target vanishes), any cover keeps all 32 of them, as A's raster would.
  cv::Mat line(128, 128, CV_8UC1, cv::Scalar(0));
  line.col(64).setTo(255);
  EXPECT_THROW(AttractorLoss(line, {.size = 32}), Error);
  const AttractorLoss any(line, {.size = 32, .keep = 0});
  EXPECT_EQ(cv::countNonZero(any.target()), 32);
  EXPECT_EQ(cv::countNonZero(any.target().col(16)), 32);
  EXPECT_THROW(AttractorLoss(line, {.size = 32, .keep = 1}), Error);
}

// N similitudes of ratio 0.3–0.58 about points spread over the plane, turned and some reflected;
// map 2 is moved far right, so its points and their images leave the canvas (the look-up's
// outside path, the hits' edge).
std::vector<AffineMap> spread_maps(int count) {
  std::vector<AffineMap> maps;
  for (int k = 0; k < count; ++k) {
    const double r = 0.3 + 0.04 * (k % 8), turn = 0.7 * k;
    const double a = r * std::cos(turn), s = r * std::sin(turn), flip = k % 3 == 1 ? -1 : 1;
    const double x = 0.2 + 0.6 * std::fmod(0.37 * k, 1.0), y = 0.2 + 0.6 * std::fmod(0.61 * k, 1.0);
    maps.push_back({a, -s * flip, s, a * flip, x, y});
    if (k == 2) maps.back().e = 1.2;
  }
  return maps;
}

TEST(attractor_loss, every_kernel_level_gives_the_scalar_levels_bits) {
  // N = 3, 6 and 8 pick the maps by VPERMPS, N = 10 by gathers (collage/detail/play_kernel.h).
  const std::vector<CpuLevel> levels = supported_cpu_levels();
  if (levels.size() < 2) GTEST_SKIP() << "this CPU runs the scalar kernels only";
  for (int size : {32, 64}) {
    const AttractorLoss scalar(testing::disc_and_square(),
                               {.size = size, .keep = 0, .level = CpuLevel::scalar});
    for (CpuLevel level : levels) {
      const AttractorLoss other(testing::disc_and_square(),
                                {.size = size, .keep = 0, .level = level});
      for (int count : {3, 6, 8, 10}) {
        const std::vector<AffineMap> maps = spread_maps(count);
        const AttractorTerms want = scalar.terms(maps), got = other.terms(maps);
        const auto where = ::testing::Message()
                           << to_string(level) << " R=" << size << " N=" << count;
        EXPECT_EQ(got.value, want.value) << where;
        EXPECT_EQ(got.spill, want.spill) << where;
        EXPECT_EQ(got.iou, want.iou) << where;
        EXPECT_EQ(got.coverage, want.coverage) << where;
        EXPECT_EQ(cv::countNonZero(scalar.raster(maps) != other.raster(maps)), 0) << where;
        EXPECT_GT(want.spill, 0) << where;
      }
    }
  }
}

TEST(attractor_loss, a_level_outside_eight_to_the_target_side_is_refused) {
  EXPECT_THROW(AttractorLoss(testing::framed_square(), {.size = 4}), Error);
  EXPECT_THROW(AttractorLoss(testing::framed_square(), {.size = 128}), Error);
  EXPECT_THROW(AttractorLoss(cv::Mat(64, 64, CV_8UC1, cv::Scalar(0)), {.size = 32}), Error);
}

}  // namespace
}  // namespace ifsfx::collage
