// SPDX-License-Identifier: Apache-2.0
// The tops rule (paper eq. 7, docs/design.md §2): where pieces overlap, the higher-numbered map is
// on top. Four maps of factor 0.6 into the corners of the unit square overlap in bands: the first
// symbol of the top address splits the square at 0.4 (the higher maps, right and top, win the
// bands); with the map order reversed the split moves to 0.6.
#include <algorithm>

#include <gtest/gtest.h>

#include "ifs/tops.h"
#include "tests/ifs/steal_test_ifs.h"

namespace ifsfx {
namespace {

// The first symbol expected at plane point (x, y) for corner maps in raster order from the
// bottom-left (index = 2·top + right), split at `split`.
int expected_symbol(double x, double y, double split, bool reversed) {
  const int right = x > split, top = y > split;
  const int n = 2 * top + right;
  return reversed ? 3 - n : n;
}

void expect_split(bool exact, bool reversed, double split) {
  Ifs F = testing::corners(0.6);
  if (reversed) std::reverse(F.maps.begin(), F.maps.end());
  const cv::Size size(100, 100);
  const Box view{0, 0, 1, 1};
  const TopSymbols tops =
      top_symbols(F, size, {.sampling = {.view = view, .quality = 16}, .exact = exact});
  const Viewport vp{view, size};
  int wrong = 0, checked = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      ASSERT_NE(tops.coverage.at<std::uint8_t>(r, c), 0);
      const Point p = vp.pixel_centre(c, r);
      // Pixels that straddle the split may go either way in the chaos game (it keeps the largest
      // address in the pixel, the descent the centre's): leave out the band next to it.
      if (!exact && (std::abs(p.x - split) < 0.011 || std::abs(p.y - split) < 0.011)) continue;
      ++checked;
      wrong += tops.first.at<std::uint16_t>(r, c) != expected_symbol(p.x, p.y, split, reversed);
    }
  // The descent is exact. The chaos game keeps the largest address among the points that
  // reached a pixel, and where the higher piece is only reached through a sparse corner of the
  // invariant measure (e.g. the right edge just above 0.4) a pixel may see none of its points.
  EXPECT_LE(wrong, exact ? 0 : checked / 1000)
      << (exact ? "exact" : "chaos game") << (reversed ? ", reversed" : "");
}

TEST(tops, higher_map_wins_overlaps_so_the_split_is_at_0_4) {
  expect_split(true, false, 0.4);
  expect_split(false, false, 0.4);
}

TEST(tops, reversing_the_map_order_moves_the_split_to_0_6) {
  expect_split(true, true, 0.6);
  expect_split(false, true, 0.6);
}

TEST(tops, second_symbol_subdivides_the_top_piece) {
  // In the top-right piece [0.4, 1]², the second symbol splits again at 0.4 + 0.6·0.4 = 0.64.
  const Ifs F = testing::corners(0.6);
  const cv::Size size(100, 100);
  const Box view{0, 0, 1, 1};
  const TopSymbols tops = top_symbols(F, size, {.sampling = {.view = view}, .exact = true});
  const Viewport vp{view, size};
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const Point p = vp.pixel_centre(c, r);
      if (p.x <= 0.4 || p.y <= 0.4) continue;
      ASSERT_EQ(tops.first.at<std::uint16_t>(r, c), 3);
      ASSERT_EQ(tops.second.at<std::uint16_t>(r, c), expected_symbol(p.x, p.y, 0.64, false))
          << p.x << ", " << p.y;
    }
}

TEST(tops, render_colours_pieces_by_first_symbol_and_leaves_the_background_transparent) {
  Ifs F = testing::corners(0.45);  // pieces apart: gaps between them
  F.colours = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const cv::Mat image =
      render_tops(F, {64, 64}, {.sampling = {.view = Box{0, 0, 1, 1}}, .exact = true});
  ASSERT_EQ(image.type(), CV_32FC4);
  EXPECT_EQ(image.at<cv::Vec4f>(63, 0), cv::Vec4f(0, 0, 1, 1));   // bottom-left: map 0, red
  EXPECT_EQ(image.at<cv::Vec4f>(63, 63), cv::Vec4f(0, 1, 0, 1));  // bottom-right: map 1, green
  EXPECT_EQ(image.at<cv::Vec4f>(0, 0), cv::Vec4f(1, 0, 0, 1));    // top-left: map 2, blue
  EXPECT_EQ(image.at<cv::Vec4f>(32, 32), cv::Vec4f(0, 0, 0, 0));  // the gap in the middle
}

}  // namespace
}  // namespace ifsfx
