// SPDX-License-Identifier: Apache-2.0
// The picture of several periods of a seamless texture (ifs/tiles.h): the tile repeated and
// shifted cyclically by whole pixels, for any pixel type and for steal maps; bad layouts refused.
#include "ifs/tiles.h"

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "same_bytes.h"

namespace ifsfx {
namespace {

// A tile whose every pixel says where it is: (col, row, col·row) in three 16-bit channels.
cv::Mat numbered_tile(cv::Size size) {
  cv::Mat tile(size, CV_16UC3);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      tile.at<cv::Vec3w>(r, c) =
          cv::Vec3w(static_cast<std::uint16_t>(c), static_cast<std::uint16_t>(r),
                    static_cast<std::uint16_t>(c * r));
  return tile;
}

TEST(tiles, the_picture_of_periods_is_the_tile_repeated) {
  const cv::Mat tile = numbered_tile({7, 5});
  const cv::Mat picture = tile_picture(tile, {.tiles = {3, 2}});
  ASSERT_EQ(picture.size(), cv::Size(21, 10));
  cv::Mat repeated;
  cv::repeat(tile, 2, 3, repeated);
  EXPECT_TRUE(testing::same_bytes(picture, repeated));
}

TEST(tiles, an_offset_starts_the_picture_inside_the_period) {
  const cv::Mat tile = numbered_tile({8, 6});
  // Half the width, a third of the height: 4 and 2 pixels.
  const TileLayout layout{.tiles = {2, 2}, .offset = {0.5, 1.0 / 3}};
  EXPECT_EQ(tile_shift(tile.size(), layout.offset), cv::Point(4, 2));
  const cv::Mat picture = tile_picture(tile, layout);
  ASSERT_EQ(picture.size(), cv::Size(16, 12));
  for (int r = 0; r < picture.rows; ++r)
    for (int c = 0; c < picture.cols; ++c)
      ASSERT_EQ(picture.at<cv::Vec3w>(r, c), tile.at<cv::Vec3w>((r + 2) % 6, (c + 4) % 8))
          << "pixel " << c << "," << r;
}

TEST(tiles, shifts_are_rounded_to_whole_pixels_and_wrap) {
  EXPECT_EQ(tile_shift({1024, 1024}, {0.5, 0.5}), cv::Point(512, 512));
  EXPECT_EQ(tile_shift({1023, 3}, {1.0 / 3, 0.9}), cv::Point(341, 0));  // 2.7 rounds to 3 ≡ 0
  EXPECT_EQ(tile_shift({10, 10}, {0, 0}), cv::Point(0, 0));
}

TEST(tiles, a_steal_map_is_laid_out_as_its_picture) {
  StealMap tile;
  tile.source_uv = cv::Mat(4, 6, CV_32FC2);
  cv::randu(tile.source_uv, 0, 1);
  tile.coverage = cv::Mat(4, 6, CV_8UC1);
  cv::randu(tile.coverage, 0, 2);
  tile.coverage *= 255;
  const TileLayout layout{.tiles = {2, 3}, .offset = {0.5, 0.25}};
  const StealMap picture = tile_picture(tile, layout);
  EXPECT_TRUE(testing::same_bytes(picture.source_uv, tile_picture(tile.source_uv, layout)));
  EXPECT_TRUE(testing::same_bytes(picture.coverage, tile_picture(tile.coverage, layout)));
  EXPECT_EQ(picture.size(), cv::Size(12, 12));
}

TEST(tiles, bad_layouts_are_refused) {
  const cv::Mat tile = numbered_tile({16, 16});
  const auto message = [&](const TileLayout& layout) {
    try {
      tile_picture(tile, layout);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({.tiles = {0, 2}}), "tiles: must be 1 to 64 periods a side (got 0x2)");
  EXPECT_EQ(message({.tiles = {65, 1}}), "tiles: must be 1 to 64 periods a side (got 65x1)");
  EXPECT_EQ(message({.offset = {1, 0}}),
            "tile offset: must be fractions of the tile in [0, 1) (got 1,0)");
  EXPECT_EQ(message({.offset = {0, std::nan("")}}),
            "tile offset: must be fractions of the tile in [0, 1) (got 0,nan)");
  EXPECT_THROW(check_tile_layout({4096, 16}, {.tiles = {9, 1}}), Error);  // 36864 pixels wide
}

}  // namespace
}  // namespace ifsfx
