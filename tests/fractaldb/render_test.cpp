// SPDX-License-Identifier: Apache-2.0
// FractalDB's pictures as the reference draws them: known answers for the fit, the flips, the
// patch stamps, the colours, the overflow rule and the names; PNG files that decode to the same
// pixels. (The pixel-for-pixel agreement with the reference itself is checked against its
// checkout by bench/fractaldb_vs_reference.sh.)
#include "fractaldb/render.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "fractaldb/dataset.h"
#include "ifs/error.h"
#include "ifs/image_io.h"

namespace ifsfx::fractaldb {
namespace {

namespace fs = std::filesystem;

// One map sending every point to (1, 1): the walk is the origin, then (1, 1) for ever.
Category to_one_one() {
  return {"one", {{0, 0, 0, 0, 1, 1}}, {1.0}};
}

constexpr Weight kOnes{1, 1, 1, 1, 1, 1};

Points walk_of(const Category& c, const DrawSettings& s, const Weight& w = kOnes) {
  return walk(c, w, s, reference_draws(s.iterations));
}

// The lit (non-zero) pixels of a canvas or image channel, as (row, column).
std::vector<cv::Point> lit(const cv::Mat& image) {
  std::vector<cv::Point> out;
  cv::Mat one = image;
  if (image.channels() == 3) cv::extractChannel(image, one, 0);
  cv::findNonZero(one, out);
  for (auto& p : out) p = {p.y, p.x};
  return out;
}

TEST(fractaldb_render, fits_the_points_between_the_paddings) {
  const DrawSettings s{.size = {512, 512}, .padding = {6, 6}, .iterations = 1000};
  const Points points = walk_of(to_one_one(), s);
  ASSERT_EQ(points.size(), 1000u);
  // x: 0 ↦ 0 / 1 · 500 + 6, 1 ↦ 1 / 1 · 500 + 6; y the same.
  EXPECT_EQ(points[0], (Pixel{6, 6}));
  for (std::size_t i = 1; i < points.size(); ++i) ASSERT_EQ(points[i], (Pixel{506, 506}));
  // Another size and padding per axis.
  const DrawSettings wide{.size = {300, 100}, .padding = {10, 2}, .iterations = 3};
  EXPECT_EQ(walk_of(to_one_one(), wide)[2], (Pixel{290, 98}));
}

TEST(fractaldb_render, point_pictures_light_the_points_in_the_four_flips) {
  const DrawSettings s{.size = {512, 512}, .iterations = 1000, .draw = DrawType::point_gray};
  const cv::Mat canvas = draw(walk_of(to_one_one(), s), s, 1);
  EXPECT_EQ(lit(canvas), (std::vector<cv::Point>{{6, 6}, {506, 506}}));
  // Flip 0 is y up; 1 flips it top-bottom (the canvas itself), 2 left-right, 3 both.
  const std::vector<std::vector<cv::Point>> expected{
      {{5, 506}, {505, 6}}, {{6, 6}, {506, 506}}, {{5, 5}, {505, 505}}, {{6, 505}, {506, 5}}};
  cv::Mat image;
  for (int flip = 0; flip < kFlips; ++flip) {
    to_image(canvas, flip, s.draw, false, image);
    EXPECT_EQ(lit(image), expected[static_cast<std::size_t>(flip)]) << "flip " << flip;
    EXPECT_EQ(image.at<cv::Vec3b>(expected[static_cast<std::size_t>(flip)][0].x,
                                  expected[static_cast<std::size_t>(flip)][0].y),
              cv::Vec3b(127, 127, 127));
  }
}

TEST(fractaldb_render, flips_are_the_reference_transposes_of_flip_0) {
  const Category c{"two", {{0.5, 0.1, 0, 0.5, 0, 0}, {0.4, 0, 0.2, 0.5, 0.5, 0.3}}, {0.4, 0.6}};
  const DrawSettings s{.size = {97, 61}, .iterations = 3000, .draw = DrawType::patch_color};
  const cv::Mat canvas = draw(walk_of(c, s), s, 5);
  cv::Mat f0, f, expected;
  to_image(canvas, 0, s.draw, false, f0);
  const int codes[] = {0, 1, -1};  // top-bottom, left-right, both
  for (int flip = 1; flip < kFlips; ++flip) {
    to_image(canvas, flip, s.draw, false, f);
    cv::flip(f0, expected, codes[flip - 1]);
    EXPECT_EQ(cv::norm(f, expected, cv::NORM_INF), 0) << "flip " << flip;
  }
  // rgb swaps red and blue.
  to_image(canvas, 0, s.draw, true, f);
  cv::Mat swapped;
  cv::cvtColor(f, swapped, cv::COLOR_RGB2BGR);
  EXPECT_EQ(cv::norm(f0, swapped, cv::NORM_INF), 0);
}

TEST(fractaldb_render, a_patch_is_stamped_per_point_one_pixel_down_and_right) {
  // Two points, far apart: two 3×3 blocks at (x + 1, y + 1), each with 1 to 9 pixels lit by its
  // mask; over many instances the masks are uniform in 1..511 (a pixel lit 256 times in 511).
  const DrawSettings s{.size = {512, 512}, .iterations = 2, .draw = DrawType::patch_gray};
  const Points points = walk_of(to_one_one(), s);
  std::array<int, 9> position_lit{};
  int blocks = 0, pixels = 0;
  for (std::uint64_t seed = 0; seed < 1000; ++seed) {
    const cv::Mat canvas = draw(points, s, seed);
    const int total = cv::countNonZero(canvas);
    const cv::Mat a = canvas(cv::Rect(7, 7, 3, 3)), b = canvas(cv::Rect(507, 507, 3, 3));
    ASSERT_EQ(cv::countNonZero(a) + cv::countNonZero(b), total) << "lit outside the blocks";
    ASSERT_GT(cv::countNonZero(a), 0);
    ASSERT_GT(cv::countNonZero(b), 0);
    for (int i = 0; i < 9; ++i)
      position_lit[static_cast<std::size_t>(i)] += a.at<uchar>(i / 3, i % 3);
    blocks += 2;
    pixels += total;
  }
  EXPECT_NEAR(static_cast<double>(pixels) / blocks, 9 * 256.0 / 511, 0.15);
  for (const int n : position_lit) EXPECT_NEAR(n / 1000.0, 256.0 / 511, 0.06);
}

TEST(fractaldb_render, a_later_patch_replaces_the_whole_block_black_pixels_too) {
  // 999 patches on one spot: the block shows the last mask alone (were they or-ed, all 9 lit).
  const DrawSettings s{.size = {512, 512}, .iterations = 1000, .draw = DrawType::patch_gray};
  const Points points = walk_of(to_one_one(), s);
  int lit_pixels = 0;
  for (std::uint64_t seed = 0; seed < 50; ++seed)
    lit_pixels += cv::countNonZero(draw(points, s, seed)(cv::Rect(507, 507, 3, 3)));
  EXPECT_LT(lit_pixels / 50.0, 6.0);
}

TEST(fractaldb_render, colours_are_the_references_hues_by_point_index) {
  const auto colours = palette(DrawType::point_color);
  ASSERT_EQ(colours.size(), 129u);
  // convert_color(i, 128) as the reference computes it (printed by its own function).
  EXPECT_EQ(colours[1 + 0], (std::array<std::uint8_t, 3>{47, 47, 191}));
  EXPECT_EQ(colours[1 + 32], (std::array<std::uint8_t, 3>{47, 191, 119}));
  EXPECT_EQ(colours[1 + 64], (std::array<std::uint8_t, 3>{191, 191, 47}));
  EXPECT_EQ(colours[1 + 100], (std::array<std::uint8_t, 3>{191, 47, 146}));
  EXPECT_EQ(colours[1 + 127], (std::array<std::uint8_t, 3>{54, 47, 191}));
  EXPECT_EQ(palette(DrawType::patch_gray).size(), 2u);
  // Point i takes hue i mod 128: the origin hue 0, the last point of 1000 hue 999 mod 128.
  const DrawSettings s{.size = {512, 512}, .iterations = 1000, .draw = DrawType::point_color};
  const cv::Mat canvas = draw(walk_of(to_one_one(), s), s, 1);
  EXPECT_EQ(canvas.at<uchar>(6, 6), 1);
  EXPECT_EQ(canvas.at<uchar>(506, 506), 1 + 999 % 128);
  cv::Mat image;
  to_image(canvas, 1, s.draw, false, image);
  EXPECT_EQ(image.at<cv::Vec3b>(6, 6), cv::Vec3b(191, 47, 47));  // BGR
}

TEST(fractaldb_render, a_weight_multiplies_the_coefficients) {
  const Category c{"two", {{0.5, 0.1, 0, 0.5, 0, 0}, {0.4, 0, 0.2, 0.5, 0.5, 0.3}}, {0.4, 0.6}};
  const Weight w{0.8, 1.2, 1, 0.6, 1.4, 0.9};
  Category scaled = c;
  for (AffineMap& f : scaled.maps) {
    f.a *= w[0], f.b *= w[1], f.c *= w[2], f.d *= w[3], f.e *= w[4], f.f *= w[5];
  }
  const DrawSettings s{.iterations = 5000};
  EXPECT_EQ(walk_of(c, s, w), walk_of(scaled, s));
  EXPECT_NE(walk_of(c, s, w), walk_of(c, s));
}

TEST(fractaldb_render, an_overflowing_walk_loses_its_points_from_100_before_the_first_nan) {
  // Weighted by 4, x ↦ 2x + 1 on both axes: infinite at step k, then 0 · ∞ makes x NaN.
  const Category c{"grows", {{0.5, 0, 0, 0.5, 1, 1}}, {1.0}};
  const Weight w{4, 1, 1, 4, 1, 1};
  std::size_t k = 0;
  for (double v = 0; !std::isinf(v); v = 2 * v + 1) ++k;
  ASSERT_EQ(k, 1024u);
  const DrawSettings s{.size = {512, 512}, .iterations = 3000, .draw = DrawType::point_gray};
  const Points points = walk_of(c, s, w);
  EXPECT_EQ(points.size(), k + 1 - 100);  // the first NaN is point k + 1
  EXPECT_EQ(points.front(), (Pixel{6, 6}));
  EXPECT_EQ(points.back(), (Pixel{506, 506}));
}

TEST(fractaldb_render, a_point_past_the_edge_is_dropped_with_no_padding) {
  // Padding 0 puts (1, 1) at column and row 512, outside: the reference fails there (point) or
  // clips (patch); here it is left out.
  const DrawSettings s{
      .size = {512, 512}, .padding = {0, 0}, .iterations = 10, .draw = DrawType::point_gray};
  const Points points = walk_of(to_one_one(), s);
  EXPECT_EQ(points.back(), (Pixel{512, 512}));
  EXPECT_EQ(lit(draw(points, s, 1)), (std::vector<cv::Point>{{0, 0}}));
  const DrawSettings patch{
      .size = {512, 512}, .padding = {0, 0}, .iterations = 10, .draw = DrawType::patch_gray};
  const cv::Mat canvas = draw(points, patch, 1);
  EXPECT_EQ(cv::countNonZero(canvas), cv::countNonZero(canvas(cv::Rect(1, 1, 3, 3))));
}

TEST(fractaldb_render, the_same_seed_gives_the_same_picture_and_masks_follow_the_seed) {
  const Category c{"two", {{0.5, 0.1, 0, 0.5, 0, 0}, {0.4, 0, 0.2, 0.5, 0.5, 0.3}}, {0.4, 0.6}};
  const DrawSettings s{.size = {128, 128}, .iterations = 2000};
  const Points points = walk_of(c, s);
  EXPECT_EQ(cv::norm(draw(points, s, 3), draw(points, s, 3), cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(draw(points, s, 3), draw(points, s, 4), cv::NORM_INF), 0);
  const DrawSettings p{.size = {128, 128}, .iterations = 2000, .draw = DrawType::point_gray};
  EXPECT_EQ(cv::norm(draw(points, p, 3), draw(points, p, 4), cv::NORM_INF), 0);
}

TEST(fractaldb_render, names_and_orders_images_as_the_reference) {
  DatasetSpec spec;
  spec.categories = {{"00007", {{0.5, 0, 0, 0.5, 0, 0}}, {1.0}},
                     {"00009", {{0.5, 0, 0, 0.5, 0, 0}}, {1.0}}};
  spec.weights = weights_table(0.1);
  spec.instances = 3;
  EXPECT_EQ(image_count(spec), 2 * 25 * 3 * 4);
  const ImageKey key{1, 3, 2, 1};
  const std::int64_t index = image_index(spec, key);
  EXPECT_EQ(index, ((1 * 25 + 3) * 3 + 2) * 4 + 1);
  EXPECT_EQ(image_key(spec, index), key);
  EXPECT_EQ(image_path(spec, key), "00009/00009_03_count_2_flip1.png");
  spec.settings.draw = DrawType::point_color;  // one picture per category and weight
  EXPECT_EQ(image_count(spec), 2 * 25 * 4);
  EXPECT_EQ(image_path(spec, image_key(spec, 7)), "00007/00007_01_count_0_flip3.png");
  // The masks of a picture follow its category's name, weight and instance, not its flip.
  spec.settings.draw = DrawType::patch_gray;
  EXPECT_EQ(mask_seed(spec, {0, 1, 2, 0}), mask_seed(spec, {0, 1, 2, 3}));
  EXPECT_NE(mask_seed(spec, {0, 1, 2, 0}), mask_seed(spec, {1, 1, 2, 0}));
  EXPECT_NE(mask_seed(spec, {0, 1, 2, 0}), mask_seed(spec, {0, 1, 1, 0}));
  spec.categories[1].name = "00007";
  EXPECT_THROW(check(spec), Error);
}

TEST(fractaldb_render, png_files_decode_to_the_images_pixels) {
  const fs::path dir =
      fs::temp_directory_path() / ("ifsfx-fractaldb-png-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Category c{"two", {{0.5, 0.1, 0, 0.5, 0, 0}, {0.4, 0, 0.2, 0.5, 0.5, 0.3}}, {0.4, 0.6}};
  // Odd widths: the 1-bit rows end in part of a byte, mirrored too.
  for (const DrawType type : {DrawType::patch_gray, DrawType::point_color}) {
    for (const bool rgb : {false, true}) {
      const DrawSettings s{.size = {61, 37}, .padding = {2, 2}, .iterations = 3000, .draw = type};
      const cv::Mat canvas = draw(walk_of(c, s), s, 9);
      for (int flip = 0; flip < kFlips; ++flip) {
        const std::string bytes = encode_png(canvas, flip, type, rgb);
        std::ofstream(dir / "p.png", std::ios::binary) << bytes;
        const cv::Mat decoded = read_image(dir / "p.png").pixels;
        cv::Mat expected;
        to_image(canvas, flip, type, false, expected);
        ASSERT_EQ(decoded.type(), CV_8UC3) << to_string(type) << " rgb " << rgb;
        EXPECT_EQ(cv::norm(decoded, expected, cv::NORM_INF), 0)
            << to_string(type) << " rgb " << rgb << " flip " << flip;
      }
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ifsfx::fractaldb
