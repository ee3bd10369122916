// SPDX-License-Identifier: Apache-2.0
// `--animate drift`: every coefficient of every map wanders smoothly in time, driven by fractal
// Brownian motion (a sum of octaves of 1-D gradient noise, each half the amplitude and twice the
// frequency of the one before, each on a lattice of its own phase). Time 0 is the base IFS; after
// it the coefficients wander independently, rather than all coming back to the base together
// every 1/speed seconds. The drifted IFS is a pure function of (base, t, seed): the same seed
// gives the same animation for any frame range or thread count.
//
// With a loop of T seconds the drift is periodic in time (docs/design.md §12): each octave is
// gradient noise on a lattice that wraps around a whole number of cells per loop, the slowest
// octave making round(T · speed) cycles (at least one), so time T is time 0 again, bit for bit,
// and the way through it is as smooth as anywhere else.
#pragma once

#include <cstdint>
#include <optional>

#include "ifs/ifs.h"

namespace ifsfx::engine {

// The largest drift amount and speed accepted: an excursion of 10 (ten times a coefficient's
// usual scale, or the attractor's size) is far past any useful animation, and beyond it the
// drifted translations leave the attractor's framing altogether.
inline constexpr double kMaxDriftAmount = 10;
inline constexpr double kMaxDriftSpeed = 1000;  // cycles per second
// The longest loop: a day. Cycles per loop (loop · speed) then stay far inside 64 bits for every
// octave.
inline constexpr double kMaxDriftLoop = 86400;

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
  // Seconds after which the drift comes back to where it began, 0 = never. The slowest octave
  // then makes max(1, round(loop · speed)) whole cycles per loop instead of `speed` per second.
  double loop = 0;
  // The size the translations (e, f) drift by a fraction of; none: the attractor's larger side
  // (attractor_bounds). A flame's drift passes its camera's view (engine/drawing.h).
  std::optional<double> extent;
};

// fBm noise in [−1, 1], zero at x = 0: octaves of gradient noise on channel `channel` of `seed`,
// at x.
double fbm(double x, std::uint64_t seed, std::uint64_t channel, int octaves);

// The same noise made periodic in x with period `cycles` ≥ 1 (whole cells of the slowest octave):
// octave o wraps its gradients around cycles · 2^o cells, so fbm_periodic(x + cycles) =
// fbm_periodic(x), and the noise is C² across the wrap as everywhere else. Zero at x = 0.
double fbm_periodic(double x, std::int64_t cycles, std::uint64_t seed, std::uint64_t channel,
                    int octaves);

// The base IFS drifted to time t (seconds). Probabilities and colours are kept.
//   Ifs now = drift(fern, frame / fps, {.amount = 0.05});
Ifs drift(const Ifs& base, double t, const DriftOptions& options = {});

}  // namespace ifsfx::engine
