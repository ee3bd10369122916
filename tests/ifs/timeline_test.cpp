// SPDX-License-Identifier: Apache-2.0
#include "ifs/timeline.h"

#include <gtest/gtest.h>

namespace ifsfx {
namespace {

TEST(timeline, frames_fall_into_steps_of_per_step_frames) {
  EXPECT_EQ(position_of_frame(0, 4), (StepPosition{0, 0.0}));
  EXPECT_EQ(position_of_frame(6, 4), (StepPosition{1, 0.5}));
  EXPECT_EQ(position_of_frame(8, 4), (StepPosition{2, 0.0}));
  EXPECT_EQ(position_of_frame(-1, 4), (StepPosition{-1, 0.75}));  // floored, not truncated
  EXPECT_EQ(position_of_frame(7, 1), (StepPosition{7, 0.0}));
}

TEST(timeline, host_times_with_rounding_errors_land_on_the_frames_they_stand_for) {
  // FFmpeg hands frame j of a 25 fps clip over as j · 0.04 · 1000 ms; at 12.5 steps per second
  // that is step j / 2.
  for (int j = 0; j < 2000; ++j) {
    const double seconds = j * 0.04 * 1000 * 0.001;
    EXPECT_EQ(position_of_steps(seconds * 12.5), position_of_frame(j, 2)) << j;
    EXPECT_EQ(position_of_steps(seconds * 25 / 3), position_of_frame(j, 3)) << j;
  }
}

TEST(timeline, positions_off_any_small_fraction_are_kept_as_given) {
  const StepPosition p = position_of_steps(2.0 + 1.0 / 3001);
  EXPECT_EQ(p.step, 2);
  EXPECT_NEAR(p.phase, 1.0 / 3001, 1e-12);
  EXPECT_EQ(position_of_steps(-0.25), (StepPosition{-1, 0.75}));
}

TEST(timeline, a_loop_holds_enough_steps_that_none_lasts_longer_than_per_step_frames) {
  EXPECT_EQ(steps_in_loop(48, 12), 4);
  EXPECT_EQ(steps_in_loop(50, 12), 5);  // 10 frames a step, not 12.5
  EXPECT_EQ(steps_in_loop(5, 12), 1);
  EXPECT_EQ(steps_in_loop(8, 1), 8);
}

TEST(timeline, frame_L_of_a_loop_is_frame_0_and_frame_L_minus_1_fades_towards_step_0) {
  EXPECT_EQ(position_in_loop(48, 12, 48), position_in_loop(0, 12, 48));
  EXPECT_EQ(position_in_loop(47, 12, 48), (StepPosition{3, 11.0 / 12}));
  EXPECT_EQ(position_in_loop(-1, 12, 48), position_in_loop(47, 12, 48));
  // 50 frames, 5 steps of 10 frames each.
  EXPECT_EQ(position_in_loop(49, 12, 50), (StepPosition{4, 0.9}));
  EXPECT_EQ(position_in_loop(125, 12, 50), (StepPosition{2, 0.5}));
}

TEST(timeline, a_loop_of_whole_steps_keeps_the_positions_of_the_endless_animation_bit_for_bit) {
  for (int k : {1, 3, 7, 12})
    for (std::int64_t j = 0; j < 20 * k; ++j)
      EXPECT_EQ(position_in_loop(j, k, 20 * k), position_of_frame(j, k)) << k << " " << j;
}

}  // namespace
}  // namespace ifsfx
