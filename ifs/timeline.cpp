// SPDX-License-Identifier: Apache-2.0
#include "ifs/timeline.h"

#include <algorithm>
#include <cmath>

namespace ifsfx {

StepPosition position_of_frame(std::int64_t frame, int per_step) {
  const std::int64_t k = per_step;
  std::int64_t step = frame / k;
  if (frame % k != 0 && frame < 0) --step;  // floor, not truncation
  return {step, static_cast<double>(frame - step * k) / static_cast<double>(k)};
}

std::int64_t steps_in_loop(std::int64_t loop_frames, int per_step) {
  const std::int64_t k = std::max(per_step, 1);
  return std::max<std::int64_t>(1, (std::max<std::int64_t>(loop_frames, 1) + k - 1) / k);
}

StepPosition position_in_loop(std::int64_t frame, int per_step, std::int64_t loop_frames) {
  const std::int64_t length = std::max<std::int64_t>(loop_frames, 1);
  const std::int64_t q = steps_in_loop(length, per_step);
  std::int64_t j = frame % length;
  if (j < 0) j += length;
  // j·Q < L·Q: a loop of up to 2^31 frames cannot overflow.
  const std::int64_t at = j * q;
  return {at / length, static_cast<double>(at % length) / static_cast<double>(length)};
}

StepPosition position_of_steps(double steps) {
  constexpr int max_denominator = 1000;
  constexpr double tolerance = 1e-9;
  if (!std::isfinite(steps)) return {};
  for (int d = 1; d <= max_denominator; ++d) {
    const double n = std::round(steps * d);
    if (std::abs(steps - n / d) <= tolerance * std::max(1.0, std::abs(steps)))
      return position_of_frame(static_cast<std::int64_t>(n), d);
  }
  const double step = std::floor(steps);
  return {static_cast<std::int64_t>(step), steps - step};
}

}  // namespace ifsfx
