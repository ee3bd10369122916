// SPDX-License-Identifier: Apache-2.0
// The conjugacy and Salem oracles of colour stealing (docs/design.md §3, issue 3), and bad input.
#include <cmath>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/steal_map.h"
#include "tests/ifs/steal_test_ifs.h"

namespace ifsfx {
namespace {

// G = L ∘ F ∘ L⁻¹ ⇒ T = L on the attractor, whatever the tops of F (here overlapping pieces).
void expect_conjugacy(bool exact, double tolerance_pixels) {
  const Ifs F = testing::corners(0.6);
  // L: rotate by 30°, scale by 0.5, centre in the unit square.
  const double c = 0.5 * std::cos(M_PI / 6), s = 0.5 * std::sin(M_PI / 6);
  const AffineMap L{c, -s, s, c, 0.5 - 0.5 * (c - s), 0.5 - 0.5 * (s + c)};
  Ifs G = F;
  for (auto& g : G.maps) g = L.compose(g).compose(*L.inverse());
  const cv::Size size(256, 256);
  const Box view{0, 0, 1, 1};
  const StealMap map =
      compute_steal_map(F, G, size, {.sampling = {.view = view, .quality = 16}, .exact = exact});
  const Viewport vp{view, size};
  const double source = 512;  // the tolerance is in pixels of a 512×512 source
  double worst = 0;
  for (int r = 0; r < size.height; ++r)
    for (int col = 0; col < size.width; ++col) {
      ASSERT_NE(map.coverage.at<std::uint8_t>(r, col), 0);
      const Point expected = L(vp.pixel_centre(col, r));
      const cv::Vec2f uv = map.source_uv.at<cv::Vec2f>(r, col);
      worst = std::max({worst, std::abs(uv[0] - expected.x) * source,
                        std::abs(uv[1] - (1 - expected.y)) * source});
    }
  EXPECT_LE(worst, tolerance_pixels) << (exact ? "exact" : "chaos game");
}

TEST(steal_map, conjugate_colouring_gives_the_conjugating_map_exactly) {
  expect_conjugacy(true, 1.0);
}

TEST(steal_map, conjugate_colouring_gives_the_conjugating_map_by_chaos_game) {
  // The chaos-game map estimates T within about a pixel of the output (here 1 output pixel is 1
  // source pixel: L halves, the source is twice the output).
  expect_conjugacy(false, 1.5);
}

// F = {x/2, x/2 + 1/2}, G = {a x, (1 − a) x + a} on the line y = 1/2 (y ↦ y/2 + 1/4 keeps the
// maps contractive): T is Salem's singular function, T(1/2) = a, T(1/4) = a², ...
TEST(steal_map, salem_pair_gives_salem_values_at_dyadic_points) {
  const double a = 1.0 / 3;
  Ifs F, G;
  F.maps = {{0.5, 0, 0, 0.5, 0, 0.25}, {0.5, 0, 0, 0.5, 0.5, 0.25}};
  G.maps = {{a, 0, 0, 0.5, 0, 0.25}, {1 - a, 0, 0, 0.5, a, 0.25}};
  // Nine pixels whose centres are x = 0, 1/8, …, 1 on y = 1/2.
  const Box view{-1.0 / 16, 0.25, 1 + 1.0 / 16, 0.75};
  const StealMap map = compute_steal_map(F, G, {9, 1}, {.sampling = {.view = view}, .exact = true});
  const auto T = [&](int eighths) {
    EXPECT_NE(map.coverage.at<std::uint8_t>(0, eighths), 0) << eighths << "/8";
    return map.source_uv.at<cv::Vec2f>(0, eighths)[0];
  };
  EXPECT_NEAR(T(4), 1.0 / 3, 1e-5);
  EXPECT_NEAR(T(2), 1.0 / 9, 1e-5);
  EXPECT_NEAR(T(6), 5.0 / 9, 1e-5);
  EXPECT_NEAR(T(1), 1.0 / 27, 1e-5);
  EXPECT_NEAR(T(5), 11.0 / 27, 1e-5);
  EXPECT_NEAR(map.source_uv.at<cv::Vec2f>(0, 4)[1], 0.5, 1e-5);  // v = 1 − y on the line
}

TEST(steal_map, colouring_with_another_number_of_maps_is_refused) {
  try {
    compute_steal_map(testing::fern(), default_colouring(3), {64, 64});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
    EXPECT_STREQ(e.what(),
                 "colouring IFS: must have as many maps as the drawing IFS (got 3 for 4)");
  }
}

TEST(steal_map, same_seed_gives_the_same_map_for_any_thread_count) {
  const Ifs F = testing::fern();
  const Ifs G = default_colouring(4);
  const StealMap one = compute_steal_map(
      F, G, {200, 160}, {.sampling = {.quality = 8, .threads = 1}, .exact = false});
  const StealMap two = compute_steal_map(
      F, G, {200, 160}, {.sampling = {.quality = 8, .threads = 2}, .exact = false});
  const StealMap five = compute_steal_map(
      F, G, {200, 160}, {.sampling = {.quality = 8, .threads = 5}, .exact = false});
  EXPECT_EQ(cv::norm(one.source_uv, two.source_uv, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(one.source_uv, five.source_uv, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(one.coverage, five.coverage, cv::NORM_INF), 0);
  const StealMap e1 =
      compute_steal_map(F, G, {200, 160}, {.sampling = {.threads = 1}, .exact = true});
  const StealMap e2 =
      compute_steal_map(F, G, {200, 160}, {.sampling = {.threads = 2}, .exact = true});
  EXPECT_EQ(cv::norm(e1.source_uv, e2.source_uv, cv::NORM_INF), 0);
}

TEST(steal_map, chaos_game_reports_its_coverage) {
  StealMapStats stats;
  const StealMap map = compute_steal_map(testing::fern(), default_colouring(4), {256, 256},
                                         {.sampling = {.quality = 16}, .exact = false}, &stats);
  EXPECT_GT(stats.points, 16u * 256 * 256 - 1);
  EXPECT_GE(stats.rounds, 1);
  EXPECT_GT(stats.hit, 0.05);
  EXPECT_NEAR(stats.coverage,
              stats.hit + static_cast<double>(stats.propagated + stats.filled) / (256 * 256),
              1e-12);
  EXPECT_NEAR(stats.coverage, cv::countNonZero(map.coverage) / (256.0 * 256), 1e-12);
}

}  // namespace
}  // namespace ifsfx
