// SPDX-License-Identifier: Apache-2.0
#include "ifs/render.h"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

// Number of s×s boxes of the mask holding at least one set pixel.
int occupied_boxes(const cv::Mat& mask, int s) {
  int n = 0;
  for (int y = 0; y < mask.rows; y += s)
    for (int x = 0; x < mask.cols; x += s) {
      const cv::Rect box(x, y, std::min(s, mask.cols - x), std::min(s, mask.rows - y));
      n += cv::countNonZero(mask(box)) > 0;
    }
  return n;
}

TEST(render_attractor, sierpinski_box_counting_dimension_is_log3_over_log2) {
  const cv::Mat mask = render_attractor(testing::sierpinski_triangle(), {1024, 1024},
                                        {.sampling = {.quality = 16, .seed = 2}});
  // Least-squares slope of log N(s) against log(1/s) over box sizes 2..64 pixels.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (int s = 2; s <= 64; s *= 2, ++n) {
    const double x = std::log(1.0 / s), y = std::log(occupied_boxes(mask, s));
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, std::log(3.0) / std::log(2.0), 0.03);
}

TEST(render_attractor, right_sierpinski_occupies_exactly_the_cells_with_disjoint_bits) {
  constexpr int k = 8, side = 1 << k;
  const cv::Mat mask =
      render_attractor(testing::right_sierpinski(), {side, side},
                       {.sampling = {.view = Box{0, 0, 1, 1}, .quality = 64, .seed = 1}});
  int wrong = 0, occupied = 0;
  for (int row = 0; row < side; ++row)
    for (int i = 0; i < side; ++i) {
      const int j = side - 1 - row;  // cells counted from the bottom: the plane has y up
      const bool expected = (i & j) == 0;
      const bool hit = mask.at<std::uint8_t>(row, i) != 0;
      occupied += hit;
      wrong += hit != expected;
    }
  EXPECT_EQ(occupied, 6561);  // 3^8
  EXPECT_EQ(wrong, 0);
}

TEST(visit_counts, total_equals_the_points_inside_the_view) {
  const Viewport whole{{-0.1, -0.1, 1.1, 1.1}, {64, 64}};
  const cv::Mat counts = visit_counts(testing::right_sierpinski(), whole, 100'000, {.seed = 1});
  EXPECT_EQ(cv::sum(counts)[0], 100'000);
}

TEST(render_measure, density_follows_the_measure) {
  // Right Sierpinski with p = (0.7, 0.15, 0.15): the bottom-left quadrant carries 70% of the
  // measure, so it must be the brightest (all maps white, so brightness is density alone).
  Ifs ifs = testing::right_sierpinski();
  ifs.probabilities = {0.7, 0.15, 0.15};
  ifs.colours = {Rgb{1, 1, 1}, Rgb{1, 1, 1}, Rgb{1, 1, 1}};
  const cv::Mat image =
      render_measure(ifs, {128, 128}, {.sampling = {.view = Box{0, 0, 1, 1}, .seed = 1}});
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  const double bottom_left = cv::mean(grey(cv::Rect(0, 64, 64, 64)))[0];
  const double bottom_right = cv::mean(grey(cv::Rect(64, 64, 64, 64)))[0];
  EXPECT_GT(bottom_left, 1.5 * bottom_right);
}

TEST(render, rejects_absurd_sizes_and_options) {
  const Ifs fern = testing::barnsley_fern();
  try {
    render_attractor(fern, {0, 100});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "size: each side must be 1 to 32768 pixels (got 0x100)");
  }
  EXPECT_THROW(render_attractor(fern, {40000, 10}), Error);
  EXPECT_THROW(render_measure(fern, {64, 64}, {.sampling = {.quality = -1}}), Error);
  EXPECT_THROW(render_measure(fern, {64, 64}, {.supersample = 0}), Error);
}

}  // namespace
}  // namespace ifsfx
