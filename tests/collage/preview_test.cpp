// SPDX-License-Identifier: Apache-2.0
#include "collage/preview.h"

#include <array>
#include <set>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

using testing::framed_square;
using testing::quadrant_maps;

Ifs quadrants() {
  Ifs ifs;
  ifs.maps = quadrant_maps();
  ifs.probabilities = default_probabilities(ifs.maps);
  return ifs;
}

TEST(preview, shows_target_collage_and_attractor_with_a_colour_per_piece) {
  const cv::Mat image = fit_preview(framed_square(), quadrants(), {.scale = 1, .quality = 64});
  const int gap = 2;  // max(2, 64 / 32)
  ASSERT_EQ(image.type(), CV_8UC3);
  ASSERT_EQ(image.size(), cv::Size(3 * 64 + 2 * gap, 64));
  EXPECT_EQ(image.at<cv::Vec3b>(32, 32), cv::Vec3b(255, 255, 255)) << "L in white";
  EXPECT_EQ(image.at<cv::Vec3b>(2, 2), cv::Vec3b(0, 0, 0)) << "outside L";
  // The quadrant maps tile L: each quadrant of panels 2 and 3 in its piece's colour, all four
  // colours different, and nothing of L missed.
  for (int panel : {1, 2}) {
    const int x0 = panel * (64 + gap);
    std::set<std::array<std::uint8_t, 3>> colours;
    // Centres of the quadrants in pixels; map k's piece is quadrant k (bottom row first).
    const cv::Point centre[] = {{20, 44}, {44, 44}, {20, 20}, {44, 20}};
    for (int k = 0; k < 4; ++k) {
      const cv::Vec3b got = image.at<cv::Vec3b>(centre[k].y, x0 + centre[k].x);
      EXPECT_EQ(got, piece_colour(k)) << "panel " << panel << " piece " << k;
      colours.insert({got[0], got[1], got[2]});
    }
    EXPECT_EQ(colours.size(), 4u);
  }
}

TEST(preview, dims_spill_and_greys_what_is_missed) {
  Ifs moved = quadrants();
  moved.maps[3].e += 0.125;  // top-right piece pushed 8 pixels right, off L
  moved.probabilities = default_probabilities(moved.maps);
  const cv::Mat image = fit_preview(framed_square(), moved, {.scale = 1, .quality = 64});
  const int x0 = 64 + 2;  // the collage panel
  EXPECT_EQ(image.at<cv::Vec3b>(20, x0 + 36), cv::Vec3b(64, 64, 64)) << "L missed: dark grey";
  const cv::Vec3b spilled = image.at<cv::Vec3b>(20, x0 + 60), full = piece_colour(3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(spilled[c], full[c] / 3.0, 0.5) << "spill: a third";
}

TEST(preview, piece_colours_differ) {
  std::set<std::array<std::uint8_t, 3>> colours;
  for (int k = 0; k < 32; ++k) {
    const cv::Vec3b c = piece_colour(k);
    colours.insert({c[0], c[1], c[2]});
  }
  EXPECT_EQ(colours.size(), 32u);
}

TEST(preview, bad_inputs_are_errors) {
  EXPECT_THROW(fit_preview(cv::Mat(8, 9, CV_8UC1), quadrants()), Error);
  EXPECT_THROW(fit_preview(framed_square(), quadrants(), {.scale = 0}), Error);
}

}  // namespace
}  // namespace ifsfx::collage
