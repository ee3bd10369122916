// SPDX-License-Identifier: Apache-2.0
#include "collage/fit.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "collage/distance.h"
#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "tests/collage/test_shapes.h"
#include "tests/common/known_ifs.h"

namespace ifsfx::collage {
namespace {

constexpr int kSize = 96;

using testing::quick;

// The Sierpinski triangle rendered from its known IFS: the target that N = 3 maps can match
// exactly. The grid is set so that the triangle's lines (at multiples of 1/32) run through pixel
// centres: on a grid whose edges run along them, the raster of the very same set changes under a
// 0.01-pixel move, and the IoU would measure the grid rather than the fit.
cv::Mat sierpinski_target() {
  constexpr int size = 97;
  const double half = 0.5 / (size - 1);
  RenderOptions r;
  r.sampling.view = Box{-half, -half, 1 + half, 1 + half};
  r.sampling.quality = 128;
  return render_attractor(testing::right_sierpinski(), {size, size}, r);
}

cv::Mat filled_square() {
  cv::Mat m(kSize, kSize, CV_8UC1, cv::Scalar(0));
  m(cv::Rect(8, 8, kSize - 16, kSize - 16)).setTo(255);
  return m;
}

void expect_bound_holds(const CollageReport& r) {
  EXPECT_TRUE(r.bound_holds()) << "the collage theorem's bound h(L,W(L))/(1-s) failed: h(L, A) "
                               << r.hausdorff << " > " << r.upper_bound << " + " << r.raster_error
                               << " (raster)";
  EXPECT_LT(r.contraction, 1);
}

TEST(fit, sierpinski_target_with_three_maps_gives_its_attractor_back) {
  FitOptions o = quick(3);
  o.max_evaluations = 4000;
  const auto result = fit(sierpinski_target(), o);
  ASSERT_EQ(result.ifs.maps.size(), 3u);
  EXPECT_GE(result.report.iou, 0.97) << "collage IoU " << result.report.collage_iou;
  expect_bound_holds(result.report);
}

TEST(fit, filled_square_with_four_maps_is_tiled) {
  FitOptions o = quick(4);
  o.max_evaluations = 3000;
  const auto result = fit(filled_square(), o);
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

TEST(fit, attractor_of_a_five_map_ifs_comes_back) {
  // Not a tiling: the five pieces overlap. The search has to find maps of the flower onto its
  // petals, which exist exactly.
  RenderOptions r;
  r.sampling.view = Box{0, 0, 1, 1};
  r.sampling.quality = 128;
  const cv::Mat flower = render_attractor(testing::five_petals(), {96, 96}, r);
  FitOptions o = quick(5);
  o.max_evaluations = 4000;
  const auto result = fit(flower, o);
  EXPECT_GE(result.report.iou, 0.95) << "collage IoU " << result.report.collage_iou;
  expect_bound_holds(result.report);
}

TEST(fit, two_components_with_two_maps_get_one_map_each) {
  const cv::Mat l = testing::disc_and_square();
  cv::Mat left = l.clone(), right = l.clone();
  left(cv::Rect(48, 0, 48, 96)).setTo(0);
  right(cv::Rect(0, 0, 48, 96)).setTo(0);
  // What the collage search does with components (one range each at least); the attractor's
  // stages may trade that for a better IoU.
  FitOptions o = quick(2);
  o.method = FitMethod::collage;
  o.max_evaluations = 3000;
  const auto result = fit(l, o);
  int on_left = 0, on_right = 0;
  for (const auto& f : result.ifs.maps) {
    const std::array<AffineMap, 1> one = {f};
    const cv::Mat image = collage_raster(l, one);
    const double area = cv::countNonZero(image);
    on_left += cv::countNonZero(image & left) > 0.8 * area;
    on_right += cv::countNonZero(image & right) > 0.8 * area;
  }
  EXPECT_EQ(on_left, 1);
  EXPECT_EQ(on_right, 1);
  ASSERT_EQ(result.report.parts.size(), 2u);
  for (const auto& part : result.report.parts) EXPECT_GT(part.covered, 0.5);
  expect_bound_holds(result.report);
}

TEST(fit, search_gives_the_same_maps_for_one_two_and_three_threads) {
  // The work budget ends it (no clock); every unit of work is split the same way whatever the
  // thread count, so the maps are the same bit for bit.
  cv::Mat l = testing::disc_and_square(64);
  l(cv::Rect(10, 30, 8, 8)).setTo(0);  // a hole in the disc
  FitOptions o = quick(3);
  o.max_evaluations = 1500;
  std::vector<FitResult> results;
  for (int threads : {1, 2, 3}) {
    o.threads = threads;
    results.push_back(fit(l, o));
  }
  for (std::size_t k = 1; k < results.size(); ++k) {
    EXPECT_EQ(results[k].ifs.maps, results[0].ifs.maps) << k + 1 << " threads";
    EXPECT_EQ(results[k].evaluations, results[0].evaluations);
    EXPECT_EQ(results[k].report.iou, results[0].report.iou);
  }
}

TEST(fit, max_seconds_holds_within_a_tenth) {
  // A 128-pixel target and more evaluations than any machine does in the time: the clock ends
  // the fit, at most 10% late (each unit of work is short, and renderings that would not end in
  // time are not started). How early it ends depends on the load: the fit keeps a reserve of its
  // slowest rendering so far, so a busy machine makes it stop sooner (2.0-2.9 s of 3 with two to
  // eight busy loops beside the ASan build, 1.9 s after a 0.6 s pause of the process): the lower
  // bound only tells that the clock, not an early exit, ended it.
  cv::Mat l(128, 128, CV_8UC1, cv::Scalar(0));
  cv::ellipse(l, {64, 64}, {54, 34}, 30, 0, 360, cv::Scalar(255), cv::FILLED);
  cv::circle(l, {90, 40}, 14, cv::Scalar(0), cv::FILLED);
  FitOptions o;
  o.maps = 6;
  o.max_seconds = 3;
  o.max_evaluations = 1000000000;
  const auto start = std::chrono::steady_clock::now();
  const auto result = fit(l, o);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(result.time_capped);
  EXPECT_LE(wall, 3.3);
  EXPECT_LE(result.seconds, 3.3);
  EXPECT_GE(wall, 1.0) << "the time was used";
  expect_bound_holds(result.report);
}

TEST(fit, moment_initialisation_is_still_there) {
  FitOptions o = quick(4);
  o.init = Initialisation::moments;
  const auto result = fit(filled_square(), o);
  EXPECT_GE(result.report.iou, 0.95);
  EXPECT_EQ(result.runs, 3) << "restarts + 1 runs, each from a split";
}

TEST(fit, progress_names_the_phases_and_the_best_iou) {
  FitOptions o = quick(3);
  o.max_evaluations = 1000;
  std::vector<FitProgress> seen;
  o.progress = [&](const FitProgress& p) { seen.push_back(p); };
  const auto result = fit(testing::disc_and_square(64), o);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().phase, FitPhase::partition);
  const auto first = [&](FitPhase phase) {
    return std::find_if(seen.begin(), seen.end(),
                        [&](const FitProgress& p) { return p.phase == phase; }) -
           seen.begin();
  };
  EXPECT_LT(first(FitPhase::partition), first(FitPhase::search));
  EXPECT_LT(first(FitPhase::search), first(FitPhase::refine));
  EXPECT_LT(first(FitPhase::refine), std::ssize(seen));
  for (std::size_t k = 1; k < seen.size(); ++k)
    EXPECT_GE(seen[k].best_iou, seen[k - 1].best_iou) << "the best IoU never falls";
  EXPECT_LE(seen.back().best_iou, result.report.iou);
  EXPECT_STREQ(to_string(FitPhase::search), "search");
}

TEST(fit, stop_request_interrupts_it) {
  std::atomic<bool> stop{true};
  FitOptions o = quick(3);
  o.cancel = CancelToken(&stop);
  for (const auto init : {Initialisation::search, Initialisation::moments}) {
    o.init = init;
    try {
      fit(filled_square(), o);
      FAIL() << "not interrupted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::interrupted);
    }
  }
}

TEST(fit, assess_reports_how_much_of_each_component_is_covered) {
  // One map that copies L into the disc only: the square is left out.
  const cv::Mat l = testing::disc_and_square();
  Ifs ifs;
  ifs.maps = {{0.3, 0, 0, 0.3, 0.1, 0.35}};
  ifs.probabilities = {1};
  const CollageReport r = assess(l, ifs, {.quality = 64});
  ASSERT_EQ(r.parts.size(), 2u);
  EXPECT_GT(r.parts[0].area, r.parts[1].area) << "largest first";
  const auto& square = r.parts[0].centre.x > 0.5 ? r.parts[0] : r.parts[1];
  EXPECT_EQ(square.covered, 0);
  EXPECT_NEAR(square.centre.x, 0.6 + 1.0 / 6, 0.02);
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

TEST(fit, collage_method_is_still_there) {
  FitOptions o = quick(4);
  o.method = FitMethod::collage;
  o.max_evaluations = 3000;
  const auto result = fit(filled_square(), o);
  EXPECT_GE(result.report.iou, 0.95);
  expect_bound_holds(result.report);
}

TEST(fit, fine_iou_is_measured_on_the_fine_raster_of_the_same_frame) {
  // The square [1/8, 7/8]² on 96² and on 384²: the same shape, four times finer.
  cv::Mat fine(4 * kSize, 4 * kSize, CV_8UC1, cv::Scalar(0));
  fine(cv::Rect(32, 32, 4 * kSize - 64, 4 * kSize - 64)).setTo(255);
  FitOptions o = quick(4);
  o.max_evaluations = 3000;
  o.fine_target = fine;
  const auto result = fit(filled_square(), o);
  EXPECT_EQ(result.report.fine_size, 4 * kSize);
  EXPECT_GE(result.report.fine_iou, 0.9);
  EXPECT_EQ(result.report.fine_iou,
            attractor_iou(fine, result.ifs, {o.quality / 4, o.seed, o.threads}));
  o.fine_target = cv::Mat();
  o.max_evaluations = 300;
  EXPECT_EQ(fit(filled_square(), o).report.fine_size, 0) << "none given, none measured";
}

TEST(fit, a_stop_request_keeps_the_best_so_far) {
  // Stop once the attractor's stages have begun: the fit returns what it had, marked.
  std::atomic<bool> stop{false};
  FitOptions o = quick(4);
  o.max_evaluations = 2000;
  o.cancel = CancelToken(&stop);
  o.progress = [&](const FitProgress& p) {
    if (p.phase == FitPhase::attractor) stop = true;
  };
  const auto result = fit(filled_square(), o);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(result.ifs.maps.size(), 4u);
  EXPECT_GT(result.report.iou, 0.5);
}

// The attractor of the shipped barnsley-fern preset, rendered 512² and taken as a picture, fitted
// with its own 4 maps at the default evaluation count (issue 32 item 5). Issue 32 asks for IoU ≥
// 0.9 on the 512² raster of the picture's frame (the preset's own maps score 0.95 there). The scan
// finds the large copy (0.84 of the whole) and both leaflets (0.34, 0.38 in the preset); the
// fourth map sits by the stem, on the right leaflet's base. Seed 3: until the working raster's
// stage screened its starts (fit_attractor.cpp, screened_start) it ended at 0.847, the 32² and 64²
// stages' fern; now 0.908, and seeds 1–8 end at 0.903–0.918 (`collage_bench --only fern --maps 4
// --max-seconds 0 --seed S`; before: 0.838–0.920, three below 0.9). A fixed evaluation count (no
// clock) makes it the same on any machine; about 20 CPU seconds in Release.
TEST(fit, fern_comes_back_from_its_own_picture_with_its_large_copy) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "about 20 CPU seconds in Release, many times that under the sanitizers; the "
                  "attractor's stages run there in the other fit tests";
#endif
  const cv::Mat picture = render_attractor(load_ifs("barnsley-fern").ifs, {512, 512});
  FitOptions o;
  o.maps = 4;
  o.seed = 3;
  o.max_seconds = 0;
  o.fine_target = working_raster(picture, {.size = 512});
  const auto result = fit(working_raster(picture, {.size = 128}), o);
  double largest = 0;
  int leaflets = 0;
  for (const auto& f : result.ifs.maps) {
    largest = std::max(largest, f.contraction());
    if (f.contraction() >= 0.25 && f.contraction() <= 0.45) ++leaflets;
  }
  EXPECT_GE(largest, 0.8);
  EXPECT_LE(largest, 0.9);
  EXPECT_EQ(leaflets, 2) << "the two leaflets";
  EXPECT_GE(result.report.iou, 0.8);
  EXPECT_GE(result.report.fine_iou, 0.9) << "issue 32's done-when line";
  expect_bound_holds(result.report);
}

}  // namespace
}  // namespace ifsfx::collage
