// SPDX-License-Identifier: Apache-2.0
// `--loop N` through the fractal engine (docs/design.md §12): frame N is frame 0, byte for byte,
// for the drift and the superIFS animation, by frame number and by a host's time, and the step
// from frame N − 1 into it changes the picture as much as the other steps do.
#include <vector>

#include <gtest/gtest.h>

#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "same_bytes.h"
#include "tests/video/test_frames.h"

namespace ifsfx::engine {
namespace {

using ifsfx::testing::same_bytes;
using video::testing::test_frame;

double mean_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  const cv::Scalar m = cv::mean(d);
  return (m[0] + m[1] + m[2]) / 3;
}

// Frames 0..n of a still input (the map alone changes) through `s`; checks frame n is frame 0
// and that the step n − 1 → n lies within the range of the steps before it (give or take
// `slack` grey levels: a crossfade's rounding).
void expect_a_seamless_loop(const FractalSettings& s, int n, double slack) {
  const cv::Size size{64, 48};
  const cv::Mat still = test_frame(size, 1);
  FractalEngine engine(s, size);
  std::vector<cv::Mat> frames;
  for (int i = 0; i <= n; ++i) frames.push_back(engine.filter(still, i));
  EXPECT_TRUE(same_bytes(frames[static_cast<std::size_t>(n)], frames[0]));
  // Later rounds of the loop too, and an engine asked for frame n + 3 first.
  EXPECT_TRUE(same_bytes(engine.filter(still, 2 * n + 3), frames[3]));
  FractalEngine later(s, size);
  EXPECT_TRUE(same_bytes(later.filter(still, n + 3), frames[3]));
  double smallest = 1e9, largest = 0;
  for (int i = 0; i + 1 < n; ++i) {
    const double d = mean_difference(frames[static_cast<std::size_t>(i)],
                                     frames[static_cast<std::size_t>(i + 1)]);
    smallest = std::min(smallest, d);
    largest = std::max(largest, d);
  }
  const double wrap =
      mean_difference(frames[static_cast<std::size_t>(n - 1)], frames[static_cast<std::size_t>(n)]);
  EXPECT_GT(smallest, 0);
  EXPECT_GE(wrap, smallest - slack);
  EXPECT_LE(wrap, largest + slack);
}

FractalSettings drift_loop() {
  FractalSettings s;
  s.drawing = load_ifs("sierpinski-triangle").ifs;
  s.animate = Animate::drift;
  s.drift_amount = 0.2;
  s.drift_speed = 0.5;
  s.keyframe_interval = 4;
  s.loop = 24;
  s.sampling.seed = 5;
  return s;
}

TEST(fractal_engine_loop, drift_frame_N_is_frame_0_and_the_last_step_is_like_the_others) {
  expect_a_seamless_loop(drift_loop(), 24, 0.5);
}

TEST(fractal_engine_loop, a_loop_that_is_no_multiple_of_the_keyframe_interval_still_closes) {
  FractalSettings s = drift_loop();
  s.loop = 22;  // 6 keyframes, 22/6 frames apart
  expect_a_seamless_loop(s, 22, 0.5);
}

TEST(fractal_engine_loop, superifs_frame_N_is_frame_0_and_the_last_step_is_like_the_others) {
  FractalSettings s;
  s.animate = Animate::superifs;
  s.superifs = "carpet-lace";
  s.keyframe_interval = 3;
  s.loop = 12;
  s.sampling.seed = 4;
  expect_a_seamless_loop(s, 12, 0.5);
}

TEST(fractal_engine_loop, a_hosts_times_give_the_frames_of_the_loop) {
  const cv::Size size{48, 40};
  const cv::Mat still = test_frame(size, 2);
  FractalEngine engine(drift_loop(), size, size, 25);
  cv::Mat at_time, later;
  // Frame 7, and frame 7 + 24 (a second round), as a host's milliseconds hand them over.
  engine.filter_at(still, 7 * 0.04 * 1000 * 0.001, at_time);
  engine.filter_at(still, 31 * 0.04 * 1000 * 0.001, later);
  EXPECT_TRUE(same_bytes(at_time, engine.filter(still, 7)));
  EXPECT_TRUE(same_bytes(later, at_time));
  // Between frames 23 and 24 = 0: a blend on the way back to frame 0.
  cv::Mat between;
  engine.filter_at(still, 23.5 / 25, between);
  EXPECT_GT(cv::norm(between, engine.filter(still, 23), cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(between, engine.filter(still, 0), cv::NORM_INF), 0);
  EXPECT_DOUBLE_EQ(engine.drift_options().loop, 24.0 / 25);
}

TEST(fractal_engine_loop, without_a_loop_frame_N_is_not_frame_0) {
  FractalSettings s = drift_loop();
  s.loop = 0;
  const cv::Size size{64, 48};
  const cv::Mat still = test_frame(size, 1);
  FractalEngine engine(s, size);
  EXPECT_GT(cv::norm(engine.filter(still, 0), engine.filter(still, 24), cv::NORM_INF), 0);
}

TEST(fractal_engine_loop, a_negative_loop_is_refused) {
  FractalSettings s = drift_loop();
  s.loop = -1;
  try {
    FractalEngine engine(s);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "loop: must be 0..1000000 frames, 0 for none (got -1)");
  }
}

}  // namespace
}  // namespace ifsfx::engine
