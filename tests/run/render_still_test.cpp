// SPDX-License-Identifier: Apache-2.0
#include "run/render_still.h"

#include <gtest/gtest.h>

#include "flame/flame_chaos.h"
#include "flame/variations.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"
#include "same_bytes.h"

namespace ifsfx::app {
namespace {

const cv::Size kSize{96, 80};

// Every mode is the library call the mode names, with the job's options (the doors' pictures
// are this function's, so they are these calls').
TEST(render_still, each_mode_is_its_library_picture) {
  const Ifs F = load_ifs("maple-leaf").ifs;
  RenderOptions options;
  options.sampling.quality = 8;
  EXPECT_TRUE(testing::same_bytes(
      render_still(F, {.mode = RenderMode::attractor, .size = kSize, .options = options}).image,
      render_attractor(F, kSize, options)));
  EXPECT_TRUE(testing::same_bytes(
      render_still(F, {.mode = RenderMode::measure, .size = kSize, .options = options}).image,
      render_measure(F, kSize, options)));
  const Rgb white{1, 1, 1};
  EXPECT_TRUE(testing::same_bytes(
      render_still(F, {.mode = RenderMode::tops,
                       .size = kSize,
                       .options = options,
                       .second_symbol = true,
                       .background = white,
                       .alpha = false})
          .image,
      tops_picture(F, kSize, {.sampling = options.sampling, .second_symbol = true}, white, false)));
}

TEST(render_still, steal_colours_the_source_through_the_map_it_returns) {
  const Ifs F = load_ifs("sierpinski-triangle").ifs;
  cv::Mat source(40, 50, CV_8UC3);
  cv::randu(source, 0, 255);
  const StillResult still =
      render_still(F, {.mode = RenderMode::steal, .size = kSize, .source = source});
  ASSERT_TRUE(still.map.has_value());
  const StealMap map = compute_steal_map(F, default_colouring(F.size()), kSize);
  EXPECT_TRUE(testing::same_bytes(still.map->coverage, map.coverage));
  const cv::Mat expected = with_coverage_alpha(apply(map, source), map.coverage, true);
  EXPECT_TRUE(testing::same_bytes(still.image, expected));
  EXPECT_GT(still.steal.levels, 0);
  EXPECT_DOUBLE_EQ(still.stats.coverage, still.steal.coverage);
}

// A flame: its attractor, tops and steal are flame_chaos's pictures; the exact descent is refused
// with the reason.
TEST(render_still, a_flame_draws_each_mode_through_the_chaos_game) {
  const flame::Variation* linear = flame::find_variation("linear");
  const flame::Variation* swirl = flame::find_variation("swirl");
  flame::Flame f;
  f.camera = {.width = 96, .height = 80, .scale = 30};
  f.xforms = {{.pre = {0.5, 0, 0, 0.5, -0.5, 0}, .variations = {{.id = linear->id}}},
              {.pre = {0.5, 0, 0, 0.5, 0.5, 0}, .variations = {{.id = swirl->id}}}};
  RenderOptions options;
  options.sampling.quality = 4;
  EXPECT_TRUE(testing::same_bytes(
      render_still(
          f, {.mode = RenderMode::attractor, .size = kSize, .options = options, .exact = false})
          .image,
      flame::flame_attractor(f, kSize, options.sampling)));
  EXPECT_TRUE(testing::same_bytes(
      render_still(f, {.mode = RenderMode::tops, .size = kSize, .options = options, .exact = false})
          .image,
      flame::flame_tops(f, kSize, {.sampling = options.sampling, .exact = false}, {}, true)));
  cv::Mat source(40, 50, CV_8UC3);
  cv::randu(source, 0, 255);
  const StillResult still = render_still(f, {.mode = RenderMode::steal,
                                             .size = kSize,
                                             .options = options,
                                             .exact = false,
                                             .source = source});
  const StealMap map = flame::flame_steal_map(f, default_colouring(2), kSize,
                                              {.sampling = options.sampling, .exact = false});
  EXPECT_TRUE(testing::same_bytes(still.image,
                                  with_coverage_alpha(apply(map, source), map.coverage, true)));
  EXPECT_THROW(render_still(f, {.mode = RenderMode::tops, .size = kSize}), Error);
}

TEST(render_still, a_steal_without_a_source_is_refused) {
  EXPECT_THROW(render_still(load_ifs("sierpinski-triangle").ifs, {.mode = RenderMode::steal}),
               Error);
}

}  // namespace
}  // namespace ifsfx::app
