// SPDX-License-Identifier: Apache-2.0
// Where an animation stands: a step of a sequence (a keyframe of the filter's maps, a texture of a
// superIFS sequence) and how far it has faded towards the next one. Every animated picture of
// ifsfx is a pure function of its position (docs/design.md §7, "Time is an argument"), whichever
// door asks: a frame number (`ifsfx filter`, a farm shard) or a time in seconds (a frei0r host).
#pragma once

#include <cstdint>

namespace ifsfx {

struct StepPosition {
  std::int64_t step = 0;  // the step shown
  double phase = 0;       // weight of step + 1 blended over it, in [0, 1)

  friend bool operator==(const StepPosition&, const StepPosition&) = default;
};

// Frame `frame` of a sequence shown `per_step` frames a step (per_step ≥ 1):
// {⌊frame / per_step⌋, (frame mod per_step) / per_step}, floored for negative frames too.
StepPosition position_of_frame(std::int64_t frame, int per_step);

// How many steps a loop of `loop_frames` frames holds when a step is shown `per_step` frames:
// ⌈loop_frames / per_step⌉, so that steps are never more than per_step frames apart (both ≥ 1).
std::int64_t steps_in_loop(std::int64_t loop_frames, int per_step);

// Frame `frame` of an animation that repeats every `loop_frames` frames (docs/design.md §12): frame
// j = frame mod loop_frames, floored, stands at j·Q / loop_frames steps, Q = steps_in_loop(…), the
// Q steps spread evenly over the loop: {⌊j·Q / L⌋, (j·Q mod L) / L}. Step Q is step 0 again (the
// caller takes steps modulo Q), so frame L is frame 0 and frame L − 1 fades towards step 0. When
// per_step divides L this is position_of_frame(j, per_step), bit for bit.
//   position_in_loop(50, 12, 48) == position_in_loop(2, 12, 48) == {0, 2.0 / 12}
StepPosition position_in_loop(std::int64_t frame, int per_step, std::int64_t loop_frames);

// A position given in steps (seconds × steps per second). Hosts hand times over with rounding
// errors (FFmpeg's frame j at 25 fps is j · 0.04 · 1000 ms), so a value within 1e-9 of a fraction
// n/d with d ≤ 1000 is read as exactly that fraction: the same position, bit for bit, as
// position_of_frame gives for the frame it stands for.
StepPosition position_of_steps(double steps);

}  // namespace ifsfx
