// SPDX-License-Identifier: Apache-2.0
// apply: colouring through a steal map by one remap, nearest and bilinear, with a background.
#include <algorithm>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/steal_map.h"

namespace ifsfx {
namespace {

// A 2×1 map: the left pixel takes the source at (u, v), the right one is off the attractor.
StealMap one_pixel_map(float u, float v) {
  StealMap map;
  map.source_uv = cv::Mat(1, 2, CV_32FC2, cv::Scalar::all(0));
  map.coverage = cv::Mat(1, 2, CV_8UC1, cv::Scalar::all(0));
  map.source_uv.at<cv::Vec2f>(0, 0) = {u, v};
  map.coverage.at<std::uint8_t>(0, 0) = 255;
  return map;
}

cv::Mat ramp() {
  // 4×1 grey source 0, 100, 200, 250: pixel centres at u = 1/8, 3/8, 5/8, 7/8.
  return (cv::Mat_<std::uint8_t>(1, 4) << 0, 100, 200, 250);
}

TEST(steal_apply, bilinear_interpolates_between_source_pixels) {
  const cv::Mat out = apply(one_pixel_map(0.5f, 0.5f), ramp());  // halfway between 100 and 200
  ASSERT_EQ(out.type(), CV_8UC1);
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 150);
}

TEST(steal_apply, nearest_takes_the_pixel_under_the_coordinate) {
  const cv::Mat out =
      apply(one_pixel_map(0.55f, 0.5f), ramp(), {.interpolation = Interpolation::nearest});
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 200);
}

TEST(steal_apply, uncovered_pixels_get_the_background) {
  const cv::Mat out = apply(one_pixel_map(0.5f, 0.5f), ramp(), {.background = cv::Scalar(77)});
  EXPECT_EQ(out.at<std::uint8_t>(0, 1), 77);
}

TEST(steal_apply, edges_repeat_the_edge_pixel_and_never_mix_in_the_background) {
  const cv::Mat out = apply(one_pixel_map(0.0f, 0.0f), ramp(), {.background = cv::Scalar(255)});
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 0);
}

TEST(steal_apply, keeps_the_source_type_and_channels) {
  const cv::Mat bgra(3, 3, CV_8UC4, cv::Scalar(1, 2, 3, 4));
  EXPECT_EQ(apply(one_pixel_map(0.5f, 0.5f), bgra).type(), CV_8UC4);
  const cv::Mat f(3, 3, CV_32FC3, cv::Scalar(0.25, 0.5, 0.75));
  const cv::Mat out = apply(one_pixel_map(0.5f, 0.5f), f);
  ASSERT_EQ(out.type(), CV_32FC3);
  EXPECT_EQ(out.at<cv::Vec3f>(0, 0), cv::Vec3f(0.25f, 0.5f, 0.75f));
}

TEST(steal_apply, prepared_map_gives_what_apply_gives_and_checks_the_source_size) {
  cv::Mat source(40, 60, CV_8UC3);
  cv::randu(source, 0, 256);
  StealMap map;
  map.source_uv = cv::Mat(30, 50, CV_32FC2);
  cv::randu(map.source_uv, 0.0, 1.0);
  map.coverage = cv::Mat(30, 50, CV_8UC1);
  cv::randu(map.coverage, 0, 2);
  map.coverage *= 255;
  const PreparedStealMap prepared = prepare_apply(map, source.size(), {.threads = 2});
  cv::Mat out;
  apply(prepared, source, out);
  EXPECT_EQ(cv::norm(out, apply(map, source), cv::NORM_INF), 0);
  try {
    apply(prepared, cv::Mat(41, 60, CV_8UC3), out);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "source image: must be the size the steal map was prepared for (60x40) (got "
                 "60x41)");
  }
}

// prepare_apply converts the map band by band on its workers: the fixed-point tables are those of
// one cv::convertMaps over the whole map (the reference), for 1 and 3 threads, bilinear and
// nearest.
TEST(steal_apply, prepared_tables_are_one_convert_maps_for_any_thread_count) {
  StealMap map;
  map.source_uv = cv::Mat(200, 70, CV_32FC2);  // 200 rows: four bands, the last one short
  cv::randu(map.source_uv, -0.1, 1.1);
  map.coverage = cv::Mat(200, 70, CV_8UC1);
  cv::randu(map.coverage, 0, 2);
  const cv::Size source(61, 47);
  cv::Mat mx(map.size(), CV_32FC1), my(map.size(), CV_32FC1);
  for (int r = 0; r < map.size().height; ++r)
    for (int c = 0; c < map.size().width; ++c) {
      const cv::Vec2f uv = map.source_uv.at<cv::Vec2f>(r, c);
      const bool covered = map.coverage.at<std::uint8_t>(r, c) != 0;
      mx.at<float>(r, c) = covered ? std::clamp(uv[0] * 61.0f - 0.5f, 0.0f, 60.0f) : -2.0f;
      my.at<float>(r, c) = covered ? std::clamp(uv[1] * 47.0f - 0.5f, 0.0f, 46.0f) : -2.0f;
    }
  for (const auto interpolation : {Interpolation::bilinear, Interpolation::nearest}) {
    cv::Mat xy, frac;
    cv::convertMaps(mx, my, xy, frac, CV_16SC2, interpolation == Interpolation::nearest);
    for (const int threads : {1, 3}) {
      const PreparedStealMap prepared =
          prepare_apply(map, source, {.interpolation = interpolation, .threads = threads});
      EXPECT_EQ(cv::norm(prepared.xy, xy, cv::NORM_INF), 0) << threads;
      ASSERT_EQ(prepared.frac.empty(), frac.empty());
      if (!frac.empty()) {
        EXPECT_EQ(cv::norm(prepared.frac, frac, cv::NORM_INF), 0) << threads;
      }
    }
  }
}

// The video filter's border: a pixel that reads nothing keeps what the output held, for 8-bit
// sources (through the compact table) and float ones (cv::remap) alike.
TEST(steal_apply, transparent_border_keeps_the_output_where_the_map_reads_nothing) {
  const cv::Mat grey = (cv::Mat_<std::uint8_t>(2, 4) << 0, 100, 200, 250, 0, 100, 200, 250);
  for (const int depth : {CV_8U, CV_32F}) {
    cv::Mat source;
    grey.convertTo(source, depth);
    const PreparedStealMap prepared = prepare_apply(one_pixel_map(0.5f, 0.5f), source.size(),
                                                    {.border = RemapBorder::transparent});
    cv::Mat out(1, 2, depth, cv::Scalar(77));
    apply(prepared, source, out);
    cv::Mat bytes;
    out.convertTo(bytes, CV_8U);
    EXPECT_EQ(bytes.at<std::uint8_t>(0, 0), 150) << depth;
    EXPECT_EQ(bytes.at<std::uint8_t>(0, 1), 77) << depth;
  }
}

TEST(steal_apply, a_transparent_border_needs_a_source_of_two_pixels_a_side) {
  EXPECT_NO_THROW(prepare_apply(one_pixel_map(0.5f, 0.5f), {4, 1}));
  try {
    prepare_apply(one_pixel_map(0.5f, 0.5f), {4, 1}, {.border = RemapBorder::transparent});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "source size: 2 to 32766 pixels a side under a transparent border (got 4x1)");
  }
}

TEST(steal_apply, empty_source_is_refused) {
  EXPECT_THROW(apply(one_pixel_map(0.5f, 0.5f), cv::Mat()), Error);
}

}  // namespace
}  // namespace ifsfx
