// SPDX-License-Identifier: Apache-2.0
// The identity oracle (docs/design.md §3): F = G = a square tiling of the unit square ⇒ T(x) = x ⇒
// stealing from a photograph gives the photograph back.
#include <gtest/gtest.h>

#include "ifs/image_io.h"
#include "ifs/steal_map.h"
#include "tests/ifs/steal_test_ifs.h"

namespace ifsfx {
namespace {

using testing::photo_path;
using testing::psnr;
using testing::square_tiling;

cv::Mat photo() {
  const cv::Mat p = read_image(photo_path()).pixels;
  EXPECT_EQ(p.type(), CV_8UC3);
  return p;
}

TEST(steal_map, identity_pair_returns_the_source_exactly_with_four_maps) {
  const cv::Mat source = photo();
  const Ifs t = square_tiling(2);
  const StealMap map = compute_steal_map(t, t, source.size(),
                                         {.sampling = {.view = Box{0, 0, 1, 1}}, .exact = true});
  EXPECT_EQ(cv::countNonZero(map.coverage), source.size().area());
  const cv::Mat out = apply(map, source);
  // Bit for bit: the descent keeps x exact, and T(x) = x to 2^-20 of the square.
  EXPECT_EQ(cv::norm(out, source, cv::NORM_INF), 0);
}

TEST(steal_map, identity_pair_returns_the_source_exactly_with_nine_maps) {
  const cv::Mat source = photo();
  const Ifs t = square_tiling(3);
  const StealMap map = compute_steal_map(t, t, source.size(),
                                         {.sampling = {.view = Box{0, 0, 1, 1}}, .exact = true});
  const cv::Mat out = apply(map, source);
  EXPECT_GE(psnr(out, source), 40);
  EXPECT_EQ(cv::norm(out, source, cv::NORM_INF), 0);
}

TEST(steal_map, identity_pair_by_chaos_game_is_within_half_a_pixel) {
  const cv::Mat source = photo();
  for (int k : {2, 3}) {
    const Ifs t = square_tiling(k);
    StealMapStats stats;
    const StealMap map = compute_steal_map(
        t, t, source.size(), {.sampling = {.view = Box{0, 0, 1, 1}, .quality = 16}, .exact = false},
        &stats);
    EXPECT_EQ(cv::countNonZero(map.coverage), source.size().area()) << k * k << " maps";
    EXPECT_GT(stats.hit, 0.99);
    EXPECT_GE(psnr(apply(map, source), source), 27) << k * k << " maps";
    // Every coordinate is within the pixel of the output pixel it stands for.
    for (int r = 0; r < map.size().height; ++r)
      for (int c = 0; c < map.size().width; ++c) {
        const cv::Vec2f uv = map.source_uv.at<cv::Vec2f>(r, c);
        ASSERT_NEAR(uv[0] * source.cols, c + 0.5, 0.5 + 1e-3);
        ASSERT_NEAR(uv[1] * source.rows, r + 0.5, 0.5 + 1e-3);
      }
  }
}

}  // namespace
}  // namespace ifsfx
