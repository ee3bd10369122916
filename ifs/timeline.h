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

// A position given in steps (seconds × steps per second). Hosts hand times over with rounding
// errors (FFmpeg's frame j at 25 fps is j · 0.04 · 1000 ms), so a value within 1e-9 of a fraction
// n/d with d ≤ 1000 is read as exactly that fraction: the same position, bit for bit, as
// position_of_frame gives for the frame it stands for.
StepPosition position_of_steps(double steps);

}  // namespace ifsfx
