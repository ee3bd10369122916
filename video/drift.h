// SPDX-License-Identifier: Apache-2.0
// `--animate drift`: every coefficient of every map wanders smoothly in time, driven by fractal
// Brownian motion (a sum of octaves of 1-D gradient noise, each half the amplitude and twice the
// frequency of the one before, each on a lattice of its own phase). Time 0 is the base IFS; after
// it the coefficients wander independently, rather than all coming back to the base together
// every 1/speed seconds. The drifted IFS is a pure function of (base, t, seed): the same seed
// gives the same animation for any frame range or thread count.
#pragma once

#include <cstdint>

#include "ifs/ifs.h"

namespace ifsfx::video {

// The largest drift amount and speed accepted: an excursion of 10 (ten times a coefficient's
// usual scale, or the attractor's size) is far past any useful animation, and beyond it the
// drifted translations leave the attractor's framing altogether.
inline constexpr double kMaxDriftAmount = 10;
inline constexpr double kMaxDriftSpeed = 1000;  // cycles per second

struct DriftOptions {
  // Largest excursion of a linear coefficient (a, b, c, d); translations (e, f) move by the same
  // fraction of the attractor's size.
  double amount = 0.1;
  double speed = 0.2;  // cycles per second of the slowest octave
  int octaves = 4;
  std::uint64_t seed = 1;
  // A drifted map whose contraction factor exceeds max(this, its base factor) is scaled back to
  // it, so the IFS stays contractive (factor < 1) and its attractor exists.
  double max_contraction = 0.95;
};

// fBm noise in [−1, 1], zero at x = 0: octaves of gradient noise on channel `channel` of `seed`,
// at x.
double fbm(double x, std::uint64_t seed, std::uint64_t channel, int octaves);

// The base IFS drifted to time t (seconds). Probabilities and colours are kept.
//   Ifs now = drift(fern, frame / fps, {.amount = 0.05});
Ifs drift(const Ifs& base, double t, const DriftOptions& options = {});

}  // namespace ifsfx::video
