#include "collage/fit.h"

#include <atomic>

#include <gtest/gtest.h>

#include "collage/distance.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "tests/common/known_ifs.h"

namespace ifsfx::collage {
namespace {

constexpr int kSize = 96;

// A small, fast fit: the evaluation budget (not the clock) ends it, so it is reproducible.
FitOptions quick(int maps) {
  FitOptions o;
  o.maps = maps;
  o.restarts = 2;
  o.max_evaluations = 12000;
  o.max_seconds = 0;
  o.quality = 128;
  return o;
}

// The Sierpinski triangle rendered from its known IFS: the target that N = 3 maps can match
// exactly. The grid is set so that the triangle's lines (at multiples of 1/32) run through pixel
// centres: on a grid whose edges run along them, the raster of the very same set changes under a
// 0.01-pixel move, and the IoU would measure the grid rather than the fit.
cv::Mat sierpinski_target() {
  constexpr int size = 97;
  const double half = 0.5 / (size - 1);
  RenderOptions r;
  r.view = Box{-half, -half, 1 + half, 1 + half};
  r.quality = 128;
  return render_attractor(testing::right_sierpinski(), {size, size}, r);
}

cv::Mat filled_square() {
  cv::Mat m(kSize, kSize, CV_8UC1, cv::Scalar(0));
  m(cv::Rect(8, 8, kSize - 16, kSize - 16)).setTo(255);
  return m;
}

void expect_bound_holds(const CollageReport& r) {
  EXPECT_LE(r.hausdorff, r.upper_bound) << "the collage theorem's bound h(L,W(L))/(1-s) failed";
  EXPECT_LT(r.contraction, 1);
}

TEST(fit, sierpinski_target_with_three_maps_gives_its_attractor_back) {
  const auto result = fit(sierpinski_target(), quick(3));
  ASSERT_EQ(result.ifs.maps.size(), 3u);
  EXPECT_GE(result.report.iou, 0.9) << "collage IoU " << result.report.collage_iou;
  expect_bound_holds(result.report);
}

TEST(fit, filled_square_with_four_maps_is_tiled) {
  const auto result = fit(filled_square(), quick(4));
  EXPECT_GE(result.report.iou, 0.95) << "collage IoU " << result.report.collage_iou;
  expect_bound_holds(result.report);
}

TEST(fit, same_seed_gives_the_same_maps_for_any_thread_count) {
  cv::Mat blob(48, 48, CV_8UC1, cv::Scalar(0));
  blob(cv::Rect(6, 10, 36, 20)).setTo(255);
  FitOptions o = quick(2);
  o.max_evaluations = 1500;
  o.restarts = 1;
  o.threads = 1;
  const auto one = fit(blob, o);
  o.threads = 2;
  const auto two = fit(blob, o);
  EXPECT_EQ(one.ifs.maps, two.ifs.maps);
  EXPECT_EQ(one.evaluations, two.evaluations);
  expect_bound_holds(one.report);
}

TEST(fit, max_seconds_stops_the_search_and_says_so) {
  FitOptions o = quick(4);
  o.max_evaluations = 100000000;
  o.max_seconds = 0.3;
  const auto result = fit(filled_square(), o);
  EXPECT_TRUE(result.time_capped);
  EXPECT_LT(result.evaluations, 100000000);
  EXPECT_EQ(result.ifs.maps.size(), 4u);
  expect_bound_holds(result.report);
}

TEST(fit, probabilities_follow_the_determinants) {
  FitOptions o = quick(4);
  o.max_evaluations = 1500;
  const auto result = fit(filled_square(), o);
  EXPECT_EQ(result.ifs.probabilities, default_probabilities(result.ifs.maps));
  EXPECT_NO_THROW(validate(result.ifs, "fitted"));
}

TEST(fit, map_count_outside_one_to_thirty_two_is_rejected) {
  for (int n : {0, -1, 33, 1000000}) {
    try {
      fit(filled_square(), quick(n));
      FAIL() << "N = " << n << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
      EXPECT_NE(std::string(e.what()).find("-n: the number of maps must be in 1..32"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace ifsfx::collage

namespace ifsfx::collage {
namespace {

// A stop request ends the search with Error{interrupted} (issue 12).
TEST(fit, a_stop_request_ends_the_search) {
  std::atomic<bool> stop{true};
  FitOptions o = quick(3);
  o.cancel = CancelToken(&stop);
  try {
    fit(filled_square(), o);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::interrupted);
  }
}

}  // namespace
}  // namespace ifsfx::collage
