// SPDX-License-Identifier: Apache-2.0
// The compacted remap against cv::remap itself, the reference: the same bytes for every 8-bit
// channel count, bilinear and nearest, constant and transparent borders, with pixels on the last
// column and row, off the source, and in between.
#include "ifs/detail/compact_remap.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace ifsfx::detail {
namespace {

// Source coordinates in pixels over [-3, W+2] × [-3, H+2], a quarter of them exactly on the
// last column or row (the edge cases of the bilinear square), converted as prepare_apply does.
void random_maps(cv::Size out, cv::Size src, bool nearest, cv::Mat& xy, cv::Mat& frac) {
  cv::RNG rng(7);
  cv::Mat mx(out, CV_32FC1), my(out, CV_32FC1);
  for (int r = 0; r < out.height; ++r)
    for (int c = 0; c < out.width; ++c) {
      float x = rng.uniform(-3.0f, src.width + 2.0f), y = rng.uniform(-3.0f, src.height + 2.0f);
      if (rng.uniform(0, 8) == 0) x = static_cast<float>(src.width - 1);
      if (rng.uniform(0, 8) == 0) y = static_cast<float>(src.height - 1);
      mx.at<float>(r, c) = x;
      my.at<float>(r, c) = y;
    }
  cv::convertMaps(mx, my, xy, frac, CV_16SC2, nearest);
}

// Inside-only coordinates (a constant border never straddles): clamped to the source.
void clamped_maps(cv::Size out, cv::Size src, cv::Mat& xy, cv::Mat& frac) {
  cv::Mat mx(out, CV_32FC1), my(out, CV_32FC1);
  cv::RNG rng(9);
  for (int r = 0; r < out.height; ++r)
    for (int c = 0; c < out.width; ++c) {
      const bool off = rng.uniform(0, 3) == 0;
      mx.at<float>(r, c) = off ? -2 : rng.uniform(0.0f, src.width - 1.0f);
      my.at<float>(r, c) = off ? -2 : rng.uniform(0.0f, src.height - 1.0f);
      if (rng.uniform(0, 6) == 0) mx.at<float>(r, c) = static_cast<float>(src.width - 1);
      if (rng.uniform(0, 6) == 0) my.at<float>(r, c) = static_cast<float>(src.height - 1);
    }
  cv::convertMaps(mx, my, xy, frac, CV_16SC2, false);
}

cv::Mat random_source(cv::Size size, int type) {
  cv::Mat source(size, type);
  cv::randu(source, 0, 256);
  return source;
}

cv::Mat through_table(const CompactRemap& table, const cv::Mat& source, const cv::Mat& start,
                      const std::optional<cv::Scalar>& background) {
  cv::Mat out = start.clone();
  remap_rows(table, source, out, {0, out.rows}, background);
  return out;
}

TEST(compact_remap, constant_border_gives_the_bytes_of_cv_remap) {
  const cv::Size src(37, 23), out(61, 41);
  const cv::Scalar background(11, 22, 33, 44);
  for (const bool nearest : {false, true})
    for (int cn = 1; cn <= 4; ++cn) {
      cv::Mat xy, frac;
      if (nearest)
        random_maps(out, src, true, xy, frac);
      else
        clamped_maps(out, src, xy, frac);
      const cv::Mat source = random_source(src, CV_8UC(cn));
      const auto table = compact_remap(xy, frac, src, RemapBorder::constant);
      ASSERT_TRUE(table) << "nearest " << nearest << " cn " << cn;
      cv::Mat expected;
      cv::remap(source, expected, xy, frac, nearest ? cv::INTER_NEAREST : cv::INTER_LINEAR,
                cv::BORDER_CONSTANT, background);
      const cv::Mat got =
          through_table(*table, source, cv::Mat::zeros(out, source.type()), background);
      EXPECT_EQ(cv::norm(got, expected, cv::NORM_INF), 0) << "nearest " << nearest << " cn " << cn;
    }
}

TEST(compact_remap, transparent_border_leaves_pixels_off_the_source_as_they_were) {
  const cv::Size src(29, 31), out(53, 47);
  for (const bool nearest : {false, true})
    for (int cn = 1; cn <= 4; ++cn) {
      cv::Mat xy, frac;
      random_maps(out, src, nearest, xy, frac);
      const cv::Mat source = random_source(src, CV_8UC(cn));
      const cv::Mat start = random_source(out, source.type());
      const auto table = compact_remap(xy, frac, src, RemapBorder::transparent);
      ASSERT_TRUE(table);
      cv::Mat expected = start.clone();
      cv::remap(source, expected, xy, frac, nearest ? cv::INTER_NEAREST : cv::INTER_LINEAR,
                cv::BORDER_TRANSPARENT);
      EXPECT_EQ(
          cv::norm(through_table(*table, source, start, std::nullopt), expected, cv::NORM_INF), 0)
          << "nearest " << nearest << " cn " << cn;
    }
}

TEST(compact_remap, every_fraction_on_every_edge_matches_cv_remap) {
  // Each of the 1024 fractions at an inner pixel, the last column, the last row and the corner
  // (a fraction leaving the source there makes the constant border straddle: those are skipped).
  const cv::Size src(3, 2);
  cv::Mat xy(4, 1024, CV_16SC2), frac(4, 1024, CV_16UC1);
  const cv::Vec2s at[4] = {{0, 0}, {2, 0}, {0, 1}, {2, 1}};
  for (int r = 0; r < 4; ++r)
    for (int f = 0; f < 1024; ++f) {
      const bool straddles = (r % 2 == 1 && f % 32 != 0) || (r >= 2 && f / 32 != 0);
      xy.at<cv::Vec2s>(r, f) = straddles ? cv::Vec2s(-5, -5) : at[r];
      frac.at<std::uint16_t>(r, f) = static_cast<std::uint16_t>(f);
    }
  const cv::Mat source = random_source(src, CV_8UC3);
  const auto table = compact_remap(xy, frac, src, RemapBorder::constant);
  ASSERT_TRUE(table);
  cv::Mat expected;
  cv::remap(source, expected, xy, frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(9));
  EXPECT_EQ(
      cv::norm(through_table(*table, source, cv::Mat::zeros(xy.size(), CV_8UC3), cv::Scalar(9)),
               expected, cv::NORM_INF),
      0);
}

TEST(compact_remap, a_square_partly_on_the_source_is_left_to_cv_remap) {
  cv::Mat xy(1, 1, CV_16SC2, cv::Scalar(-1, 0)), frac(1, 1, CV_16UC1, cv::Scalar(5));
  EXPECT_FALSE(compact_remap(xy, frac, {4, 4}, RemapBorder::constant));
  EXPECT_TRUE(compact_remap(xy, frac, {4, 4}, RemapBorder::transparent));
  EXPECT_FALSE(compact_remap(xy, cv::Mat(), {1, 4}, RemapBorder::constant));
}

// The table is built in bands of rows on the workers and joined in row order: every field is the
// same for any thread count, over several bands, bilinear and nearest; and one band whose square
// lies partly on the source gives no table, whichever worker met it.
TEST(compact_remap, the_table_is_the_same_for_any_thread_count) {
  const cv::Size src(37, 23), out(53, 301);  // 301 rows: five bands, the last one short
  for (const bool nearest : {false, true})
    for (const RemapBorder border : {RemapBorder::constant, RemapBorder::transparent}) {
      cv::Mat xy, frac;
      if (border == RemapBorder::constant && !nearest)
        clamped_maps(out, src, xy, frac);
      else
        random_maps(out, src, nearest, xy, frac);
      const auto one = compact_remap(xy, frac, src, border, 1);
      ASSERT_TRUE(one);
      for (const int threads : {2, 3, 8}) {
        const auto many = compact_remap(xy, frac, src, border, threads);
        ASSERT_TRUE(many);
        EXPECT_EQ(many->row_runs, one->row_runs);
        EXPECT_EQ(many->row_entries, one->row_entries);
        ASSERT_EQ(many->runs.size(), one->runs.size());
        for (std::size_t i = 0; i < one->runs.size(); ++i) {
          EXPECT_EQ(many->runs[i].begin, one->runs[i].begin);
          EXPECT_EQ(many->runs[i].end, one->runs[i].end);
        }
        EXPECT_EQ(many->pixel, one->pixel);
        EXPECT_EQ(many->weight, one->weight);
      }
      EXPECT_EQ(one->row_runs.size(), static_cast<std::size_t>(out.height) + 1);
      EXPECT_EQ(one->row_entries.back(), one->pixel.size());
    }
  cv::Mat xy, frac;
  clamped_maps(out, src, xy, frac);
  xy.at<cv::Vec2s>(250, 7) = cv::Vec2s(-1, 0);  // partly on the source, in the fourth band
  frac.at<std::uint16_t>(250, 7) = 5;
  for (const int threads : {1, 2, 8})
    EXPECT_FALSE(compact_remap(xy, frac, src, RemapBorder::constant, threads)) << threads;
}

}  // namespace
}  // namespace ifsfx::detail
