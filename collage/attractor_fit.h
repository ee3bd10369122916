// SPDX-License-Identifier: Apache-2.0
// Moving all maps at once on the attractor loss (attractor_loss.h, issue 32): CMA-ES (optimise.h)
// in contractive coordinates (map_params.h), so every candidate contracts, and the stochastic
// escape of the published fractal fitters — perturb all maps, re-optimise, accept by a
// Metropolis rule — for the local minima the attractor is full of.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "collage/attractor_loss.h"
#include "collage/optimise.h"
#include "ifs/affine_map.h"
#include "ifs/cancel.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

struct AttractorRefineOptions {
  Point centre{0.5, 0.5};    // the coordinates' centre: L's centroid
  double max_factor = 0.97;  // every candidate's contraction stays below it
  double sigma = 0.1;        // CMA-ES's first step in coordinates (radians, logits, 0.1 plane)
  long max_evaluations = 2000;
  std::uint64_t seed = 1;
  int threads = 0;  // candidates of a generation in parallel; 0 = all cores
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  std::function<void(const CmaesProgress&)> progress;
  CancelToken cancel;
};

struct AttractorRefined {
  std::vector<AffineMap> maps;
  double value = 0;  // the loss of `maps`
  long evaluations = 0;
  bool deadline_reached = false;
};

// CMA-ES on `loss` from `start` (whose maps are first pulled below max_factor). Deterministic for
// a seed and an evaluation count, whatever the thread count. The result is never worse than the
// (pulled) start.
//   auto r = refine_on_attractor(AttractorLoss(raster, {.size = 32}), start, {.centre = c});
AttractorRefined refine_on_attractor(const AttractorLoss& loss, std::span<const AffineMap> start,
                                     const AttractorRefineOptions& options = {});

// All maps moved at random in contractive coordinates: every coordinate gets a normal step of
// `scale` (radians, logits, 0.1 plane units) drawn from `rng`; reflections are kept.
std::vector<AffineMap> perturbed(std::span<const AffineMap> maps, Point centre, double max_factor,
                                 double scale, Rng& rng);

// The Metropolis rule: a change of the loss by `delta` is accepted when it is a gain, and with
// probability exp(−delta / temperature) when it is a loss; `u` is a uniform draw in [0, 1).
bool metropolis_accepts(double delta, double temperature, double u);

}  // namespace ifsfx::collage
