// SPDX-License-Identifier: Apache-2.0
#include "ifs/view.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

TEST(attractor_bounds, fern_bounding_box_is_the_known_one) {
  const Box b = attractor_bounds(testing::barnsley_fern());
  EXPECT_NEAR(b.x0, -2.1819, 0.01);
  EXPECT_NEAR(b.x1, 2.6558, 0.01);
  EXPECT_NEAR(b.y0, 0.0, 0.01);
  EXPECT_NEAR(b.y1, 9.9983, 0.01);
}

TEST(attractor_bounds, a_tiling_fills_the_unit_square) {
  const Box b = attractor_bounds(testing::square_grid(3));
  EXPECT_NEAR(b.x0, 0, 1e-6);
  EXPECT_NEAR(b.y0, 0, 1e-6);
  EXPECT_NEAR(b.x1, 1, 1e-6);
  EXPECT_NEAR(b.y1, 1, 1e-6);
}

TEST(fit_view, keeps_the_aspect_and_holds_the_box_with_its_margin) {
  const Box v = fit_view({0, 0, 1, 2}, {400, 100}, 0.05);
  EXPECT_NEAR(v.width() / v.height(), 4.0, 1e-12);
  EXPECT_NEAR(v.height(), 2.2, 1e-12);   // 2 + 2·0.05·2
  EXPECT_NEAR(v.x0 + v.x1, 1.0, 1e-12);  // centred
  EXPECT_NEAR(v.y0, -0.1, 1e-12);
}

// A margin that is no number, negative or absurd frames nothing useful (a NaN view draws a black
// picture): every caller of the library — the command line, the plugins — gets the same refusal.
TEST(fit_view, refuses_a_margin_that_is_not_a_sane_number) {
  for (const double margin : {std::nan(""), -0.01, 10.5, 1e300, HUGE_VAL}) {
    try {
      fit_view({0, 0, 1, 1}, {64, 64}, margin);
      ADD_FAILURE() << "margin " << margin << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
      EXPECT_TRUE(std::string(e.what()).starts_with("margin: must be a number in [0, 10]"))
          << e.what();
    }
  }
  EXPECT_NO_THROW(fit_view({0, 0, 1, 1}, {64, 64}, 0));
  EXPECT_NO_THROW(fit_view({0, 0, 1, 1}, {64, 64}, kMaxMargin));
}

TEST(viewport, pixel_centres_and_pixels_agree) {
  const Viewport vp{{0, 0, 2, 1}, {200, 100}};
  const Point c = vp.pixel_centre(0, 0);
  EXPECT_DOUBLE_EQ(c.x, 0.005);
  EXPECT_DOUBLE_EQ(c.y, 0.995);  // row 0 is the top of the plane rectangle
  const Point p = vp.plane_to_pixel()(vp.pixel_centre(17, 42));
  EXPECT_DOUBLE_EQ(p.x, 17.5);
  EXPECT_DOUBLE_EQ(p.y, 42.5);
}

TEST(parse_size, reads_w_x_h_and_rejects_the_rest) {
  EXPECT_EQ(parse_size("1920x1080"), cv::Size(1920, 1080));
  for (const char* bad : {"1920", "axb", "10x", "0x10", "40000x10", "1.5x2", "-5x5"})
    EXPECT_THROW(parse_size(bad), Error) << bad;
  try {
    parse_size("12by7");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_STREQ(e.what(), "size: expected WxH (got '12by7')");
  }
}

TEST(parse_box, reads_four_numbers_and_rejects_empty_rectangles) {
  const Box b = parse_box("0,-1.5,2,3e0");
  EXPECT_EQ(b, (Box{0, -1.5, 2, 3}));
  EXPECT_THROW(parse_box("0,0,1"), Error);
  EXPECT_THROW(parse_box("0,0,1,nan"), Error);
  try {
    parse_box("1,0,0,1");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "view: needs x1 > x0 and y1 > y0 (got '1,0,0,1')");
  }
}

}  // namespace
}  // namespace ifsfx
