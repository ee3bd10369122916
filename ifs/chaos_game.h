// SPDX-License-Identifier: Apache-2.0
// The chaos game (random iteration, docs/design.md §1): x_k = f_σk(x_{k-1}), σk drawn with the map
// probabilities. Many independent walkers, each with its own burn-in and its own random stream
// derived from (seed, chunk); chunks are fixed by the work size, never by the thread count, so the
// same seed gives the same result for any number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "ifs/cancel.h"
#include "ifs/ifs.h"

namespace ifsfx {

// The most chaos-game points per output pixel a renderer accepts (its `quality`): a 32768² raster
// at this density is 10^15 points, hours of work, but a count that fits its integer.
inline constexpr double kMaxQuality = 1e6;

struct ChaosGameOptions {
  std::uint64_t seed = 1;
  int threads = 0;  // worker threads; 0 = all cores
  // Points discarded per walker before plotting; 0 = enough for s^burn_in < 1e-9 (at least 64).
  int burn_in = 0;
  CancelToken cancel;  // polled once per chunk of points: Error{interrupted} on a stop request
};

// Burn-in iterations that bring any start within 1e-9 (relative) of the attractor.
int default_burn_in(const Ifs& ifs);

// A point of the attractor with the map that put it there (σk).
struct Sample {
  Point p;
  std::uint32_t map = 0;
};

// `count` chaos-game points (after burn-in), in a fixed order for a given seed.
std::vector<Sample> chaos_game_samples(const Ifs& ifs, std::size_t count,
                                       const ChaosGameOptions& options = {});

}  // namespace ifsfx
