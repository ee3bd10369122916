// SPDX-License-Identifier: Apache-2.0
// Chaos-game tops against exact tops (docs/design.md §3: the descent is the test oracle of the
// chaos-game renderer): the same first symbol on ≥ 98 % of the pixels both cover. Pixels that
// straddle a piece boundary may legitimately differ.
#include <gtest/gtest.h>

#include "ifs/tops.h"
#include "tests/ifs/steal_test_ifs.h"

namespace ifsfx {
namespace {

double agreement(const Ifs& F) {
  const cv::Size size(512, 512);
  const TopSymbols chaos = top_symbols(F, size, {.sampling = {.quality = 16}, .exact = false});
  const TopSymbols exact = top_symbols(F, size, {.exact = true});
  EXPECT_EQ(chaos.view, exact.view);
  int both = 0, same = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      if (!chaos.coverage.at<std::uint8_t>(r, c) || !exact.coverage.at<std::uint8_t>(r, c))
        continue;
      ++both;
      same += chaos.first.at<std::uint16_t>(r, c) == exact.first.at<std::uint16_t>(r, c);
    }
  EXPECT_GT(both, 1000) << F.name;
  return static_cast<double>(same) / both;
}

TEST(tops, chaos_game_agrees_with_exact_on_the_fern) {
  EXPECT_GE(agreement(testing::fern()), 0.98);
}

TEST(tops, chaos_game_agrees_with_exact_on_the_maple_leaf) {
  EXPECT_GE(agreement(testing::maple_leaf()), 0.98);
}

TEST(tops, chaos_game_agrees_with_exact_where_pieces_overlap) {
  EXPECT_GE(agreement(testing::corners(0.6)), 0.98);
}

}  // namespace
}  // namespace ifsfx
