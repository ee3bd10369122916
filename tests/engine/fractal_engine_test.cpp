// SPDX-License-Identifier: Apache-2.0
#include "engine/fractal_engine.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "flame/flame_chaos.h"
#include "flame/variations.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "interrupted.h"
#include "tests/video/test_frames.h"

namespace ifsfx::engine {
namespace {

using ifsfx::testing::interrupted;
using video::testing::test_frame;

FractalSettings drifting() {
  FractalSettings s;
  s.drawing = load_ifs("sierpinski-triangle").ifs;
  s.sampling.quality = 4;
  s.animate = Animate::drift;
  s.drift_amount = 0.3;
  s.drift_speed = 2;
  s.keyframe_interval = 3;
  s.sampling.seed = 5;
  s.sampling.threads = 2;
  return s;
}

TEST(fractal_engine, drifting_frames_asked_for_backwards_or_from_the_middle_are_the_same) {
  const cv::Size size{64, 48};
  const int n = 10;
  FractalEngine forward(drifting(), size), backward(drifting(), size), middle(drifting(), size);
  std::vector<cv::Mat> frames;
  for (int i = 0; i < n; ++i) frames.push_back(forward.filter(test_frame(size, i), i));
  for (int i = n - 1; i >= 0; --i)
    EXPECT_EQ(cv::norm(backward.filter(test_frame(size, i), i), frames[i], cv::NORM_INF), 0) << i;
  for (int i : {7, 2, 9, 0})  // a shard starting mid-clip, a scrubbing editor
    EXPECT_EQ(cv::norm(middle.filter(test_frame(size, i), i), frames[i], cv::NORM_INF), 0) << i;
  // It moves: keyframes 0 and 3 differ.
  EXPECT_GT(cv::norm(frames[0], forward.filter(test_frame(size, 0), 9), cv::NORM_INF), 0);
}

TEST(fractal_engine, a_time_on_the_frame_grid_is_that_frame_and_between_frames_a_blend) {
  const cv::Size size{48, 40};
  FractalEngine engine(drifting(), size, size, 25);
  const cv::Mat frame = test_frame(size, 1);
  cv::Mat at_time, between;
  // Frame 7 at 25 fps, as a host with rounding errors in its clock hands it over.
  engine.filter_at(frame, 7 * 0.04 * 1000 * 0.001, at_time);
  EXPECT_EQ(cv::norm(at_time, engine.filter(frame, 7), cv::NORM_INF), 0);
  // Halfway between frames 7 and 8 is neither.
  engine.filter_at(frame, 7.5 / 25, between);
  EXPECT_GT(cv::norm(between, at_time, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(between, engine.filter(frame, 8), cv::NORM_INF), 0);
}

TEST(fractal_engine, superifs_keyframes_are_a_function_of_the_frame_number) {
  FractalSettings s;
  s.animate = Animate::superifs;
  s.keyframe_interval = 2;
  s.buffers = 2;
  s.sampling.seed = 3;
  const cv::Size size{40, 40};
  FractalEngine forward(s, size), backward(s, size);
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 12; ++i) frames.push_back(forward.filter(test_frame(size, i), i));
  for (int i = 11; i >= 0; --i)
    EXPECT_EQ(cv::norm(backward.filter(test_frame(size, i), i), frames[i], cv::NORM_INF), 0) << i;
  EXPECT_EQ(forward.name(), "paper-fig4");
}

TEST(fractal_engine, mix_and_background_change_without_new_maps) {
  FractalSettings a;
  a.drawing = load_ifs("maple-leaf").ifs;
  FractalSettings b = a;
  b.mix = 0.5;
  b.background = parse_background("original");
  EXPECT_TRUE(same_maps(a, b));
  b.sampling.seed = 2;
  EXPECT_FALSE(same_maps(a, b));

  const cv::Size size{50, 30};
  const cv::Mat frame = test_frame(size, 0);
  FractalEngine engine(a, size);
  engine.set_look(0.5, parse_background("original"));
  b.sampling.seed = 1;
  EXPECT_EQ(
      cv::norm(engine.filter(frame, 0), FractalEngine(b, size).filter(frame, 0), cv::NORM_INF), 0);
  EXPECT_THROW(engine.set_look(1.5, {}), Error);
}

// The filter samples as `ifsfx render` does: the library's sampling defaults, the exact descent.
TEST(fractal_engine, settings_default_to_the_library_sampling) {
  const FractalSettings s;
  EXPECT_EQ(s.sampling, Sampling{});
  EXPECT_EQ(s.exact, StealMapOptions{}.exact);
  const FractalEngine engine(s);
  EXPECT_EQ(engine.map_options().sampling, Sampling{});
  EXPECT_TRUE(engine.map_options().exact);
}

TEST(fractal_engine, bad_settings_fail_before_any_frame) {
  FractalSettings s;
  std::get<Ifs>(s.drawing).maps[1].e = std::nan("");  // a coefficient that is not a number
  EXPECT_THROW(FractalEngine{s}, Error);
  s.drawing = load_ifs("barnsley-fern").ifs;
  s.colouring = load_ifs("sierpinski-triangle").ifs;
  try {
    FractalEngine engine(s);
    FAIL() << "a 3-map colouring of a 4-map IFS was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "colouring: must have as many maps as barnsley-fern (got 3 for 4)");
  }
  s.colouring.reset();
  s.mix = -1;
  EXPECT_THROW(FractalEngine{s}, Error);
}

TEST(fractal_engine, draws_the_shipped_fern_by_default) {
  EXPECT_EQ(FractalSettings{}.drawing, Drawing(load_ifs(kDefaultPreset).ifs));
  EXPECT_EQ(FractalEngine(FractalSettings{}).name(), "barnsley-fern");
}

// Every map the engine builds — the fixed map (chaos game or exact descent), the drift's framing
// and keyframes, the superIFS burn-in — polls settings.cancel, so that `ifsfx filter` and `cam`
// stop within a fraction of a second on Ctrl-C (issue 12). The flag is set before the call: the
// test proves the polling without timing anything.
// Two xforms and a final one: a flame as the engine's drawing (docs/flames.md).
flame::Flame spiral_flame() {
  const auto term = [](const char* name, double w) {
    const flame::Variation* v = flame::find_variation(name);
    return flame::VariationTerm{.id = v->id, .weight = w, .params = flame::default_parameters(*v)};
  };
  flame::Flame f;
  f.name = "spiral";
  f.camera = {.width = 48, .height = 40, .scale = 14};
  f.xforms = {{.pre = {0.6, -0.2, 0.2, 0.6, 0.5, 0},
               .variations = {term("linear", 0.8), term("swirl", 0.2)}},
              {.pre = {0.5, 0, 0, 0.5, -0.5, 0.2}, .variations = {term("spherical", 1)}}};
  f.final_xform = flame::Xform{.variations = {term("linear", 1)}};
  return f;
}

TEST(fractal_engine, a_flame_colours_frames_through_its_steal_map_and_drifts_its_affine_parts) {
  const cv::Size size{48, 40};
  FractalSettings s;
  s.drawing = spiral_flame();
  s.sampling.quality = 4;
  s.sampling.seed = 3;
  FractalEngine fixed(s, size);
  const flame::Flame& f = std::get<flame::Flame>(s.drawing);
  const StealMap T = flame::flame_steal_map(f, default_colouring(2), size,
                                            {.sampling = s.sampling, .exact = false});
  const cv::Mat frame = test_frame(size, 0);
  EXPECT_EQ(
      cv::norm(fixed.filter(frame, 0),
               filter_frame(frame, prepare_filter(T, size), fixed.filter_options()), cv::NORM_INF),
      0);
  EXPECT_EQ(fixed.name(), "spiral");
  // The drift moves the pre-affine maps only.
  const auto moved = std::get<flame::Flame>(drift(Drawing(f), 1.5, {.amount = 0.3, .seed = 2}));
  EXPECT_NE(moved.xforms[0].pre, f.xforms[0].pre);
  EXPECT_EQ(moved.xforms[0].variations, f.xforms[0].variations);
  EXPECT_EQ(moved.final_xform, f.final_xform);
  s.animate = Animate::drift;
  s.drift_amount = 0.3;
  s.drift_speed = 2;
  s.keyframe_interval = 3;
  FractalEngine drifting(s, size);
  EXPECT_EQ(cv::norm(drifting.filter(frame, 0), fixed.filter(frame, 0), cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(drifting.filter(frame, 9), fixed.filter(frame, 9), cv::NORM_INF), 0);
  // G must have one map per xform.
  s.colouring = default_colouring(3);
  EXPECT_THROW(FractalEngine{s}, Error);
}

TEST(fractal_engine, a_stop_request_ends_every_map_build) {
  std::atomic<bool> stop{true};
  const cv::Size size{64, 48};
  FractalSettings fixed;
  fixed.drawing = load_ifs("maple-leaf").ifs;
  fixed.exact = false;  // the chaos game's map
  fixed.sampling.cancel = CancelToken(&stop);
  EXPECT_TRUE(interrupted([&] { FractalEngine engine(fixed, size); }));
  FractalSettings exact = fixed;
  exact.exact = true;
  EXPECT_TRUE(interrupted([&] { FractalEngine engine(exact, size); }));
  FractalSettings framed = drifting();  // the drift's framing from the attractor's bounds
  framed.sampling.cancel = fixed.sampling.cancel;
  EXPECT_TRUE(interrupted([&] { FractalEngine engine(framed, size); }));
  FractalSettings viewed = framed;  // a given view: the keyframes, built on worker threads
  viewed.sampling.view = Box{-1, -1, 1, 1};
  EXPECT_TRUE(interrupted([&] {
    FractalEngine engine(viewed, size);
    engine.filter(test_frame(size, 0), 0);
  }));
  FractalSettings super;
  super.animate = Animate::superifs;
  super.buffers = 2;
  super.sampling.cancel = fixed.sampling.cancel;
  EXPECT_TRUE(interrupted([&] { FractalEngine engine(super, size); }));
  // Without a request the same settings make frames.
  stop = false;
  for (const FractalSettings& s : {fixed, exact, viewed, super}) {
    FractalEngine engine(s, size);
    EXPECT_EQ(engine.filter(test_frame(size, 0), 0).size(), size);
  }
}

}  // namespace
}  // namespace ifsfx::engine
