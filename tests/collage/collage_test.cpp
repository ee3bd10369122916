// SPDX-License-Identifier: Apache-2.0
#include "collage/collage.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "collage/distance.h"
#include "collage/fit.h"
#include "ifs/error.h"
#include "tests/collage/test_shapes.h"
#include "tests/common/known_ifs.h"

namespace ifsfx::collage {
namespace {

using testing::framed_square;
using testing::quadrant_maps;

// The filled equilateral triangle of side 1, base on y = 0 (the Sierpinski triangle's hull), as a
// working raster: the pixels whose centres lie inside it.
cv::Mat filled_triangle(int size) {
  cv::Mat m(size, size, CV_8UC1, cv::Scalar(0));
  const double h = std::sqrt(3.0) / 2;
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      const double x = (c + 0.5) / size, y = 1 - (r + 0.5) / size;
      if (y >= 0 && y <= h * 2 * x && y <= h * 2 * (1 - x)) m.at<std::uint8_t>(r, c) = 255;
    }
  return m;
}

// h(L, W(L)) by brute force over the exact point sets (pixel centres and their exact images),
// in plane units: the slow reference for collage_distance.
double reference_collage_distance(const cv::Mat& target, const std::vector<AffineMap>& maps) {
  const int n = target.cols;
  std::vector<Point> l, w;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      if (target.at<std::uint8_t>(r, c)) l.push_back({(c + 0.5) / n, 1 - (r + 0.5) / n});
  for (const auto& f : maps)
    for (const auto& p : l) w.push_back(f(p));
  auto directed = [](const std::vector<Point>& a, const std::vector<Point>& b) {
    double worst = 0;
    for (const auto& p : a) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& q : b) best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(directed(l, w), directed(w, l));
}

TEST(collage, filled_triangle_under_sierpinski_maps_is_sqrt3_over_12_away) {
  // W(L) is three half-size triangles; the missing middle triangle's centre is its inradius,
  // √3/12 of the side, from them (docs/design.md §6 oracle).
  constexpr int size = 128;
  const cv::Mat l = filled_triangle(size);
  const double expected = std::sqrt(3.0) / 12;
  EXPECT_NEAR(collage_distance(l, testing::sierpinski_triangle().maps), expected, 2.0 / size);
}

TEST(collage, report_brackets_the_hausdorff_distance_to_the_attractor) {
  // s = 1/2: h/(1 + s) = 0.0962 ≤ h(L, A) ≤ h/(1 − s) = 0.2887; the gasket's largest hole makes
  // h(L, A) itself √3/12 ≈ 0.1443.
  constexpr int size = 128;
  const cv::Mat l = filled_triangle(size);
  const CollageReport r = assess(l, testing::sierpinski_triangle(), {.quality = 64});
  const double tolerance = 2.0 / size;
  EXPECT_NEAR(r.contraction, 0.5, 1e-12);
  EXPECT_NEAR(r.lower_bound, 0.0962, tolerance);
  EXPECT_NEAR(r.upper_bound, 0.2887, 2 * tolerance);
  EXPECT_GE(r.hausdorff, r.lower_bound);
  EXPECT_LE(r.hausdorff, r.upper_bound);
  EXPECT_TRUE(r.bound_holds());
  EXPECT_DOUBLE_EQ(r.raster_error, std::sqrt(0.5) / 128);
  EXPECT_NEAR(r.hausdorff, std::sqrt(3.0) / 12, tolerance);
}

TEST(collage, distance_is_an_upper_bound_within_half_a_pixel_diagonal) {
  constexpr int size = 24;
  cv::Mat l(size, size, CV_8UC1, cv::Scalar(0));
  cv::ellipse(l, {12, 12}, {9, 5}, 30, 0, 360, cv::Scalar(255), cv::FILLED);
  const std::vector<std::vector<AffineMap>> cases = {
      testing::square_grid(2).maps,
      {{0.6, 0.1, -0.2, 0.5, 0.1, 0.3}, {0.3, -0.3, 0.3, 0.3, 0.5, 0.2}},
      {{0.45, 0, 0, 0.7, 0.02, -0.05}, {0.5, 0.2, 0.1, -0.4, 0.4, 0.8}, {0.2, 0, 0, 0.2, 0.9, 0.9}},
  };
  for (const auto& maps : cases) {
    const double exact = reference_collage_distance(l, maps);
    const double fast = collage_distance(l, maps);
    EXPECT_GE(fast, exact - 1e-9);
    EXPECT_LE(fast, exact + std::sqrt(2.0) / 2 / size + 1e-9);
  }
}

TEST(collage, quadrant_maps_tile_the_square) {
  cv::Mat l(64, 64, CV_8UC1, cv::Scalar(255));
  l.row(0).setTo(0);  // not full: keep it a shape with an outside
  cv::Mat square(64, 64, CV_8UC1, cv::Scalar(0));
  square(cv::Rect(8, 8, 48, 48)).setTo(255);
  // Maps of [1/8, 7/8]² onto its four quadrants.
  const double k = 0.5, lo = 0.125, mid = 0.5;
  const std::vector<AffineMap> maps = {
      rectangle_map(lo, lo, 1 - lo, 1 - lo, lo, lo, mid, mid),
      rectangle_map(lo, lo, 1 - lo, 1 - lo, mid, lo, 1 - lo, mid),
      rectangle_map(lo, lo, 1 - lo, 1 - lo, lo, mid, mid, 1 - lo),
      rectangle_map(lo, lo, 1 - lo, 1 - lo, mid, mid, 1 - lo, 1 - lo)};
  EXPECT_DOUBLE_EQ(maps[0].a, k);
  EXPECT_DOUBLE_EQ(iou(collage_raster(square, maps), square), 1.0);
  EXPECT_LE(collage_distance(square, maps), std::sqrt(2.0) / 64);
  const ObjectiveTerms t = CollageObjective(square).terms(maps);
  EXPECT_DOUBLE_EQ(t.collage_iou, 1.0);
  EXPECT_NEAR(t.overlap, 0, 1e-12);
}

TEST(collage, objective_prefers_the_tiling_to_perturbed_maps) {
  const CollageObjective objective(framed_square());
  const auto quadrants = quadrant_maps();
  auto shifted = quadrants;
  shifted[0].e += 0.05;
  auto shrunk = quadrants;
  for (auto& f : shrunk) f.a *= 0.8, f.d *= 0.8;
  auto expansive = quadrants;
  expansive[1].a = 1.2;
  EXPECT_LT(objective(quadrants), objective(shifted));
  EXPECT_LT(objective(quadrants), objective(shrunk));
  EXPECT_GT(objective(expansive), 1.0) << "a map with factor ≥ 0.97 hits the wall";
}

TEST(collage, footprints_match_a_plain_reference) {
  // W(L) and the spill of the objective, by the definitions, one image point at a time.
  const cv::Mat l = filled_triangle(48);
  const std::vector<AffineMap> maps = {{0.5, 0.1, -0.05, 0.45, 0.02, 0.01},
                                       {-0.4, 0, 0, 0.5, 0.9, 0.3},
                                       {0.3, -0.3, 0.3, 0.3, 0.6, -0.2}};  // partly off L
  const CollageObjective objective(l);
  const cv::Mat d = distance_to(l);
  cv::Mat w(48, 48, CV_8UC1, cv::Scalar(0));
  double spill = 0;
  long points = 0;
  for (const auto& f : maps) {
    const AffineMap m = plane_to_pixel(48).compose(f.compose(*plane_to_pixel(48).inverse()));
    for (int r = 0; r < 48; ++r)
      for (int c = 0; c < 48; ++c) {
        if (!l.at<std::uint8_t>(r, c)) continue;
        const Point q = m({c + 0.5, r + 0.5});
        spill += interpolated_distance(d, q.x, q.y);
        ++points;
        const int qc = static_cast<int>(std::floor(q.x)), qr = static_cast<int>(std::floor(q.y));
        if (qc >= 0 && qr >= 0 && qc < 48 && qr < 48) w.at<std::uint8_t>(qr, qc) = 255;
      }
  }
  const ObjectiveTerms t = objective.terms(maps);
  EXPECT_DOUBLE_EQ(t.collage_iou, iou(w, l));
  EXPECT_NEAR(t.spill, spill / static_cast<double>(points) / 48, 1e-12);
}

TEST(collage, iterating_a_tiling_keeps_the_tile) {
  const CollageObjective objective(framed_square());
  for (int k : {1, 2, 5}) EXPECT_EQ(objective.iterated(quadrant_maps(), k), 0) << k;
}

TEST(collage, iterating_the_sierpinski_maps_on_the_triangle_empties_it_by_quarters) {
  // W^k(L) of the filled triangle keeps 3^k of its 4^k sub-triangles: IoU(L, W^k(L)) = (3/4)^k,
  // up to the raster (whose rounding fattens the small triangles of later steps a little).
  const CollageObjective objective(filled_triangle(128));
  const auto maps = testing::sierpinski_triangle().maps;
  for (int k : {1, 2}) EXPECT_NEAR(1 - objective.iterated(maps, k), std::pow(0.75, k), 0.03) << k;
  EXPECT_LT(objective.iterated(maps, 2), objective.iterated(maps, 3));
}

TEST(collage, bad_inputs_are_errors) {
  const cv::Mat empty(16, 16, CV_8UC1, cv::Scalar(0));
  const std::vector<AffineMap> one = {{0.5, 0, 0, 0.5, 0, 0}};
  EXPECT_THROW(collage_distance(empty, one), Error);
  const cv::Mat l = filled_triangle(16);
  EXPECT_THROW(collage_distance(l, {}), Error);
  const std::vector<AffineMap> nan = {{std::nan(""), 0, 0, 0.5, 0, 0}};
  EXPECT_THROW(collage_distance(l, nan), Error);
  EXPECT_THROW(CollageObjective(cv::Mat(16, 20, CV_8UC1, cv::Scalar(255))), Error);
  EXPECT_THROW(CollageObjective(l).iterated(one, 0), Error);
  EXPECT_THROW(CollageObjective(l).footprint(nan[0]), Error);
}

}  // namespace
}  // namespace ifsfx::collage
