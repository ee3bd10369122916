// SPDX-License-Identifier: Apache-2.0
#include "engine/fractal_filter.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "tests/video/test_frames.h"

namespace ifsfx::engine {
namespace {

using video::testing::identity_map;
using video::testing::test_frame;

TEST(fractal_filter, identity_map_returns_the_frame) {
  const cv::Size size{97, 61};
  const cv::Mat frame = test_frame(size, 3);
  for (Interpolation mode : {Interpolation::bilinear, Interpolation::nearest}) {
    const PreparedStealMap table = prepare_filter(identity_map(size), size, mode);
    const cv::Mat out = filter_frame(frame, table);
    // Inside, exactly the frame; the last column and row sit 1/32 px inside the source edge.
    const cv::Rect inner(0, 0, size.width - 1, size.height - 1);
    EXPECT_EQ(cv::norm(out(inner), frame(inner), cv::NORM_INF), 0.0);
    EXPECT_LE(cv::norm(out, frame, cv::NORM_INF), 8.0);
    EXPECT_GT(cv::PSNR(out, frame), 50.0);
  }
}

TEST(fractal_filter, four_channel_frames_pass_their_alpha_through) {
  // A mirror with half the output uncovered: colours are stolen across the frame, alpha stays
  // where it was, pixel for pixel, and the three colour channels are what a BGR frame gives.
  const cv::Size size{41, 31};
  StealMap map = identity_map(size);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      map.source_uv.at<cv::Vec2f>(r, c)[0] = (size.width - c - 0.5f) / size.width;
  map.coverage(cv::Rect(0, 0, 10, size.height)).setTo(0);
  const cv::Mat bgr = test_frame(size, 4);
  cv::Mat alpha(size, CV_8UC1);
  cv::randu(alpha, 0, 256);
  cv::Mat bgra;
  cv::merge(std::vector<cv::Mat>{bgr, alpha}, bgra);
  const PreparedStealMap table = prepare_filter(map, size, Interpolation::nearest);
  const FilterOptions options{.mix = 0.25, .background = {BackgroundKind::colour, {10, 20, 30}}};
  cv::Mat out(size, CV_8UC4, cv::Scalar::all(7));  // written in place
  const std::uint8_t* buffer = out.data;
  filter_frame(bgra, table, options, out);
  EXPECT_EQ(out.data, buffer);
  std::vector<cv::Mat> channels;
  cv::split(out, channels);
  EXPECT_EQ(cv::norm(channels[3], alpha, cv::NORM_INF), 0.0);
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>(channels.begin(), channels.begin() + 3), colour);
  EXPECT_EQ(cv::norm(colour, filter_frame(bgr, table, options), cv::NORM_INF), 0.0);
}

TEST(fractal_filter, mirror_map_flips_the_frame) {
  const cv::Size size{40, 30};
  StealMap map = identity_map(size);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      map.source_uv.at<cv::Vec2f>(r, c)[0] = (size.width - c - 0.5f) / size.width;
  const cv::Mat frame = test_frame(size, 0);
  cv::Mat flipped;
  cv::flip(frame, flipped, 1);
  const cv::Mat out = filter_frame(frame, prepare_filter(map, size, Interpolation::nearest));
  EXPECT_EQ(cv::norm(out, flipped, cv::NORM_INF), 0.0);
}

TEST(fractal_filter, map_of_another_size_resamples_the_frame) {
  // A 20x10 output from a 40x20 frame through the identity of the unit square: each output pixel
  // takes the frame at its own centre, i.e. between four frame pixels (their mean, bilinear).
  const cv::Size frame_size{40, 20}, out_size{20, 10};
  const cv::Mat frame = test_frame(frame_size, 1);
  const cv::Mat out = filter_frame(frame, prepare_filter(identity_map(out_size), frame_size));
  ASSERT_EQ(out.size(), out_size);
  cv::Mat expected;
  cv::resize(frame, expected, out_size, 0, 0, cv::INTER_AREA);
  EXPECT_LE(cv::norm(out(cv::Rect(0, 0, 19, 9)), expected(cv::Rect(0, 0, 19, 9)), cv::NORM_INF),
            1.0);
}

TEST(fractal_filter, uncovered_pixels_take_the_background) {
  const cv::Size size{32, 24};
  StealMap map = identity_map(size);
  map.coverage(cv::Rect(0, 0, 16, 24)).setTo(0);  // left half off the attractor
  const cv::Mat frame = test_frame(size, 2);
  const PreparedStealMap table = prepare_filter(map, size);
  const cv::Rect left(0, 0, 16, 24), right(16, 0, 15, 23);

  FilterOptions colour;
  colour.background = parse_background("#102030");
  cv::Mat out = filter_frame(frame, table, colour);
  EXPECT_EQ(cv::norm(out(left), cv::Mat(left.size(), CV_8UC3, cv::Scalar(0x30, 0x20, 0x10)),
                     cv::NORM_INF),
            0.0);
  EXPECT_EQ(cv::norm(out(right), frame(right), cv::NORM_INF), 0.0);

  FilterOptions original;
  original.background = parse_background("original");
  out = filter_frame(frame, table, original);
  EXPECT_EQ(cv::norm(out(left), frame(left), cv::NORM_INF), 0.0);
}

TEST(fractal_filter, mix_blends_the_original_frame) {
  const cv::Size size{32, 24};
  StealMap map = identity_map(size);
  map.coverage.setTo(0);  // all black fractal, so the mix is A · frame
  const cv::Mat frame = test_frame(size, 4);
  const PreparedStealMap table = prepare_filter(map, size);
  FilterOptions o;
  o.mix = 1;
  EXPECT_EQ(cv::norm(filter_frame(frame, table, o), frame, cv::NORM_INF), 0.0);
  o.mix = 0.5;
  cv::Mat half;
  frame.convertTo(half, CV_8UC3, 0.5);
  EXPECT_LE(cv::norm(filter_frame(frame, table, o), half, cv::NORM_INF), 1.0);
  o.mix = 1.5;
  EXPECT_THROW(filter_frame(frame, table, o), Error);
}

TEST(fractal_filter, cross_fade_weights_the_two_maps) {
  const cv::Size size{32, 24};
  const cv::Mat frame = test_frame(size, 5);
  StealMap dark = identity_map(size);
  dark.coverage.setTo(0);
  const PreparedStealMap a = prepare_filter(identity_map(size), size);
  const PreparedStealMap b = prepare_filter(dark, size);
  EXPECT_EQ(cv::norm(filter_frame(frame, a, b, 0.0), filter_frame(frame, a), cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(filter_frame(frame, a, b, 1.0), filter_frame(frame, b), cv::NORM_INF), 0.0);
  cv::Mat quarter;
  filter_frame(frame, a).convertTo(quarter, CV_8UC3, 0.75);
  EXPECT_LE(cv::norm(filter_frame(frame, a, b, 0.25), quarter, cv::NORM_INF), 1.0);
}

// The compact table (8-bit frames, our own bands) gives cv::remap's bytes: the same frames through
// the same table with and without it, for 3 and 4 channels, both interpolations, a colour and the
// original as background, with and without mix, through one map and a cross-fade of two.
TEST(fractal_filter, compact_table_gives_the_bytes_of_cv_remap) {
  const cv::Size size{203, 151};  // odd, so that bands and rows do not line up with anything
  StealMap map = identity_map(size);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      map.source_uv.at<cv::Vec2f>(r, c) = {0.05f + 0.93f * c / size.width,
                                           0.02f + 0.97f * r * r / (size.height * size.height)};
      if ((r * 7 + c * 3) % 11 == 0) map.coverage.at<std::uint8_t>(r, c) = 0;
    }
  StealMap other = identity_map(size);
  for (const int type : {CV_8UC3, CV_8UC4}) {
    cv::Mat frame = test_frame(size, 4);
    if (type == CV_8UC4) cv::cvtColor(frame, frame, cv::COLOR_BGR2BGRA);
    for (const Interpolation mode : {Interpolation::bilinear, Interpolation::nearest}) {
      const PreparedStealMap table = prepare_filter(map, size, mode);
      const PreparedStealMap second = prepare_filter(other, size, mode);
      ASSERT_TRUE(table.compact) << "no compact table: the test would prove nothing";
      PreparedStealMap plain = table, plain_second = second;
      plain.compact.reset();
      plain_second.compact.reset();
      for (const BackgroundKind kind : {BackgroundKind::colour, BackgroundKind::original})
        for (const double mix : {0.0, 0.3}) {
          FilterOptions o;
          o.background = {kind, cv::Scalar(10, 200, 40, 255)};
          o.mix = mix;
          EXPECT_EQ(
              cv::norm(filter_frame(frame, table, o), filter_frame(frame, plain, o), cv::NORM_INF),
              0.0)
              << "type " << type << " mode " << static_cast<int>(mode) << " mix " << mix;
          EXPECT_EQ(cv::norm(filter_frame(frame, table, second, 0.4, o),
                             filter_frame(frame, plain, plain_second, 0.4, o), cv::NORM_INF),
                    0.0);
        }
    }
  }
}

TEST(fractal_filter, thread_count_does_not_change_pixels) {
  const cv::Size size{200, 150};
  StealMap map = identity_map(size);
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      map.source_uv.at<cv::Vec2f>(r, c) = {0.3f + 0.4f * c / size.width,
                                           0.1f + 0.8f * r * r / (size.height * size.height)};
  const cv::Mat frame = test_frame(size, 6);
  FilterOptions one, many;
  one.threads = 1;
  many.threads = 7;
  EXPECT_EQ(
      cv::norm(filter_frame(frame, prepare_filter(map, size, Interpolation::bilinear, 1), one),
               filter_frame(frame, prepare_filter(map, size, Interpolation::bilinear, 7), many),
               cv::NORM_INF),
      0.0);
}

TEST(fractal_filter, frame_of_the_wrong_size_is_refused) {
  const PreparedStealMap table = prepare_filter(identity_map({16, 16}), {16, 16});
  try {
    filter_frame(test_frame({17, 16}, 0), table);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "source image: must be the size the steal map was prepared for (16x16) (got "
                 "17x16)");
  }
}

TEST(fractal_filter, refuses_other_frame_types_and_a_map_with_a_constant_border) {
  const StealMap map = identity_map({16, 16});
  try {
    filter_frame(cv::Mat(16, 16, CV_8UC1, cv::Scalar(1)), prepare_filter(map, {16, 16}));
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "fractal filter: frame must be 8-bit BGR or BGRA (got type 0)");
  }
  try {
    filter_frame(test_frame({16, 16}, 0), prepare_apply(map, {16, 16}));
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "fractal filter: needs a map prepared with a transparent border (got constant)");
  }
}

TEST(fractal_filter, parse_background_reads_names_and_colours) {
  EXPECT_EQ(parse_background("black").kind, BackgroundKind::colour);
  EXPECT_EQ(parse_background("black").colour, cv::Scalar::all(0));
  EXPECT_EQ(parse_background("original").kind, BackgroundKind::original);
  EXPECT_EQ(parse_background("#ff8000").colour, cv::Scalar(0, 128, 255));
  EXPECT_EQ(parse_background("1,2,3").colour, cv::Scalar(3, 2, 1));
  try {
    parse_background("purple");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_STREQ(e.what(),
                 "background: expected black, white, original, #rrggbb or R,G,B (got 'purple')");
  }
  EXPECT_THROW(parse_background("1,2,300"), Error);
}

}  // namespace
}  // namespace ifsfx::engine
