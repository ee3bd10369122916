// SPDX-License-Identifier: Apache-2.0
#include "collage/search.h"
#include "collage/similarity_cover.h"
#include "collage/similarity_scan.h"

#include <array>
#include <atomic>
#include <chrono>

#include <gtest/gtest.h>

#include "collage/collage.h"
#include "collage/distance.h"
#include "collage/initialise.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "tests/collage/test_shapes.h"
#include "tests/common/known_ifs.h"

namespace ifsfx::collage {
namespace {

using testing::framed_square;
using testing::quadrant_maps;

// The pixels of the framed square in quadrant q (the order of quadrant_maps).
cv::Mat quadrant(int q) {
  cv::Mat piece(64, 64, CV_8UC1, cv::Scalar(0));
  const int x = q % 2 ? 32 : 8, y = q / 2 ? 8 : 32;  // rows go down, the plane's y up
  piece(cv::Rect(x, y, 24, 24)).setTo(255);
  return piece;
}

// IoU of f(L) with the piece: how well one map covers its range.
double cover(const cv::Mat& target, const AffineMap& f, const cv::Mat& piece) {
  const std::array<AffineMap, 1> one = {f};
  return iou(collage_raster(target, one), piece);
}

TEST(search, piece_score_is_lowest_for_the_map_onto_the_piece) {
  const cv::Mat square = framed_square();
  const auto maps = quadrant_maps();
  const double exact = piece_score(square, quadrant(0), maps[0]);
  EXPECT_LT(exact, 0.05) << "f(L) is the piece: nothing missed, nothing spilled";
  EXPECT_GT(piece_score(square, quadrant(0), maps[3]), exact + 0.5) << "the opposite quadrant";
  AffineMap small = maps[0];
  small.a *= 0.6, small.d *= 0.6;
  EXPECT_GT(piece_score(square, quadrant(0), small), exact + 0.2) << "covers a third of it";
}

TEST(search, finds_the_quadrant_maps_of_a_square) {
  const cv::Mat square = framed_square();
  const cv::Mat labels = partition(square, 4);
  const auto found = search_pieces(square, labels, 4);
  ASSERT_EQ(found.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    ASSERT_FALSE(found[static_cast<std::size_t>(k)].empty());
    const cv::Mat piece = labels == k;
    const Candidate& best = found[static_cast<std::size_t>(k)].front();
    EXPECT_GE(cover(square, best.map, piece), 0.9) << "piece " << k;
    EXPECT_NEAR(std::abs(best.map.det()), 0.25, 0.05) << "piece " << k;
    for (std::size_t i = 1; i < found[static_cast<std::size_t>(k)].size(); ++i)
      EXPECT_GE(found[static_cast<std::size_t>(k)][i].score, best.score) << "best first";
  }
}

TEST(search, pieces_of_another_component_are_reached_by_squashing_the_whole) {
  // Two bars side by side, one piece each: the map onto a bar squeezes both bars into it. An
  // affine image keeps the bars' gap, so it covers at most 2/3 of the bar.
  cv::Mat bars(64, 64, CV_8UC1, cv::Scalar(0));
  bars(cv::Rect(8, 8, 16, 48)).setTo(255);
  bars(cv::Rect(40, 8, 16, 48)).setTo(255);
  const cv::Mat labels = partition(bars, 2, {.by_component = true});
  const auto found = search_pieces(bars, labels, 2);
  for (int k = 0; k < 2; ++k) {
    const std::array<AffineMap, 1> one = {found[static_cast<std::size_t>(k)].front().map};
    const cv::Mat image = collage_raster(bars, one), piece = labels == k;
    EXPECT_GE(iou(image, piece), 0.55) << "piece " << k;
    EXPECT_GE(cv::countNonZero(image & piece), 0.9 * cv::countNonZero(image))
        << "piece " << k << ": the image stays on its bar";
  }
}

TEST(search, result_does_not_depend_on_the_thread_count) {
  cv::Mat blob = framed_square();
  blob(cv::Rect(8, 8, 20, 20)).setTo(0);  // an L-shape
  const cv::Mat labels = partition(blob, 3);
  SearchOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const auto a = search_pieces(blob, labels, 3, one);
  const auto b = search_pieces(blob, labels, 3, three);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].size(), b[k].size());
    for (std::size_t i = 0; i < a[k].size(); ++i) {
      EXPECT_EQ(a[k][i].map, b[k][i].map);
      EXPECT_EQ(a[k][i].score, b[k][i].score);
    }
  }
}

TEST(search, deadline_cuts_the_scan_but_every_piece_keeps_a_candidate) {
  SearchOptions late;
  late.deadline = std::chrono::steady_clock::now();
  const cv::Mat square = framed_square();
  const auto found = search_pieces(square, partition(square, 4), 4, late);
  ASSERT_EQ(found.size(), 4u);
  for (const auto& piece : found) EXPECT_FALSE(piece.empty());
}

TEST(search, stop_request_interrupts_it) {
  std::atomic<bool> stop{true};
  SearchOptions o;
  o.cancel = CancelToken(&stop);
  try {
    search_pieces(framed_square(), partition(framed_square(), 2), 2, o);
    FAIL() << "not interrupted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::interrupted);
  }
}

TEST(search, bad_inputs_are_errors) {
  const cv::Mat square = framed_square();
  EXPECT_THROW(search_pieces(square, cv::Mat(64, 64, CV_8UC1), 2), Error) << "labels type";
  EXPECT_THROW(search_pieces(square, partition(square, 2), 0), Error);
  SearchOptions o;
  o.angles = 0;
  EXPECT_THROW(search_pieces(square, partition(square, 2), 2, o), Error);
  EXPECT_THROW(piece_score(square, cv::Mat(64, 64, CV_8UC1, cv::Scalar(0)), {}), Error);
}

// The right Sierpinski triangle drawn from its IFS into the unit square with a margin of 0.1 of
// its side (as a working raster frames a shape), and its maps in that frame: x/2 + b becomes
// u/2 + (b + 0.05) / 1.2 under u = (x + 0.1) / 1.2.
struct FramedSierpinski {
  cv::Mat raster;
  std::vector<AffineMap> maps;
};

FramedSierpinski framed_sierpinski(int size) {
  RenderOptions r;
  r.sampling.view = Box{-0.1, -0.1, 1.1, 1.1};
  r.sampling.quality = 64;
  FramedSierpinski out{render_attractor(testing::right_sierpinski(), {size, size}, r), {}};
  for (const AffineMap& f : testing::right_sierpinski().maps)
    out.maps.push_back({0.5, 0, 0, 0.5, (f.e + 0.05) / 1.2, (f.f + 0.05) / 1.2});
  return out;
}

// The largest distance between the images under f and g of the square's centre and corners, or
// under f and g ∘ the reflection in the diagonal, whichever is less: the framed triangle is
// symmetric in it, so that each half is the image of the whole under two maps.
double apart(const AffineMap& f, const AffineMap& g) {
  const auto distance = [&](const AffineMap& h) {
    double d = 0;
    for (const Point& p : {Point{0.5, 0.5}, Point{0, 0}, Point{1, 0}, Point{0, 1}, Point{1, 1}}) {
      const Point a = f(p), b = h(p);
      d = std::max(d, std::hypot(a.x - b.x, a.y - b.y));
    }
    return d;
  };
  return std::min(distance(g), distance(g.compose({0, 1, 1, 0, 0, 0})));
}

// A similarity scan small enough for a test: similarities only, 15° apart. On 128² a pixel of
// the triangle's raster is often only partly the triangle's, so that even its own maps keep
// 0.92–0.96 of their points in it (a fern's on 256²: 0.98).
SimilarityScanOptions small_scan() {
  SimilarityScanOptions o;
  o.fine_precision = 0.9;
  o.scales = 7;
  o.min_scale = 0.3;
  o.angles = 24;
  o.anisotropies = {};
  o.candidates = 300;
  return o;
}

TEST(similarity_scan, finds_the_three_half_size_copies_of_a_sierpinski_triangle) {
  // The grid's scales (0.3 · 3^(i/6)) miss 1/2 by 4%: the fine polish closes that.
  const FramedSierpinski t = framed_sierpinski(128);
  const auto copies = scan_self_similarity(t.raster, small_scan());
  ASSERT_GE(copies.size(), 3u);
  for (const AffineMap& truth : t.maps) {
    double nearest = 1;
    for (const SelfCopy& c : copies) nearest = std::min(nearest, apart(c.map, truth));
    EXPECT_LT(nearest, 0.02) << "a true map, within 2.5 pixels of the 128² raster";
  }
  for (const SelfCopy& c : copies) {
    EXPECT_GE(c.precision, 0.9);
    EXPECT_LE(c.map.contraction(), 0.95 + 1e-9);
  }
  EXPECT_NEAR(copies.front().area, 0.25, 0.03) << "the largest exact copies are the halves";
}

TEST(similarity_scan, greedy_cover_of_a_sierpinski_triangle_is_its_own_ifs) {
  const FramedSierpinski t = framed_sierpinski(128);
  const auto covers =
      greedy_covers(t.raster, scan_self_similarity(t.raster, small_scan()), {.maps = 3});
  ASSERT_FALSE(covers.empty());
  ASSERT_EQ(covers.front().size(), 3u);
  std::vector<bool> matched(3, false);
  for (const AffineMap& f : covers.front())
    for (std::size_t k = 0; k < 3; ++k)
      if (apart(f, t.maps[k]) < 0.02) matched[k] = true;
  EXPECT_EQ(matched, std::vector<bool>(3, true)) << "each of the three halves, once";
}

TEST(similarity_scan, does_not_depend_on_the_thread_count) {
  const FramedSierpinski t = framed_sierpinski(96);
  SimilarityScanOptions one = small_scan(), two = small_scan();
  one.threads = 1;
  two.threads = 3;
  const auto a = scan_self_similarity(t.raster, one), b = scan_self_similarity(t.raster, two);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].map, b[i].map) << i;
}

TEST(similarity_scan, bad_inputs_are_errors) {
  const cv::Mat square = framed_square();
  EXPECT_THROW(scan_self_similarity(cv::Mat(64, 32, CV_8UC1, cv::Scalar(255))), Error);
  SimilarityScanOptions o;
  o.max_scale = 1;
  EXPECT_THROW(scan_self_similarity(square, o), Error);
  o = {};
  o.anisotropies = {1.5};
  EXPECT_THROW(scan_self_similarity(square, o), Error);
  EXPECT_THROW(scan_self_similarity(cv::Mat(64, 64, CV_8UC1, cv::Scalar(0))), Error) << "empty";
  EXPECT_THROW(greedy_covers(square, {}, {.maps = 0}), Error);
  EXPECT_TRUE(greedy_covers(square, {}, {.maps = 2}).empty()) << "fewer copies than maps";
}

}  // namespace
}  // namespace ifsfx::collage
