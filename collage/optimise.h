// SPDX-License-Identifier: Apache-2.0
// Derivative-free minimisation for the collage fit: CMA-ES (Hansen's covariance matrix
// adaptation evolution strategy, (μ/μ_w, λ) with rank-one and rank-μ updates and cumulative
// step-size adaptation). The collage objective is piecewise constant on the pixel grid and full of
// local minima, which is what an evolution strategy tolerates and a gradient method does not.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "ifs/cancel.h"

namespace ifsfx::collage {

struct CmaesProgress {
  int generation = 0;
  long evaluations = 0;  // of this run
  double best = 0;       // best value so far in this run
  double sigma = 0;      // current step size
};

struct CmaesOptions {
  double sigma = 0.1;  // initial step size, in the units of x
  int population = 0;  // λ, candidates per generation; 0 = 4 + ⌊3 ln n⌋
  long max_evaluations = 10000;
  // Stop when this time is reached (checked once per generation). The default never comes. A
  // deadline makes the result depend on the machine's speed; the evaluation budget does not.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  double min_sigma = 1e-7;    // stop when every coordinate's step is below this
  int stall_generations = 0;  // stop after this many without a gain of 1e-7; 0 = 20 + 30n/λ
  std::uint64_t seed = 1;
  int threads = 0;  // candidates of a generation are evaluated in parallel; 0 = all cores
  // Called after every generation (on the calling thread).
  std::function<void(const CmaesProgress&)> progress;
  // Polled before every generation; a stop request throws Error{interrupted}.
  CancelToken cancel;
};

struct CmaesResult {
  std::vector<double> x;  // the best point evaluated
  double value = 0;
  long evaluations = 0;
  int generations = 0;
  bool deadline_reached = false;
};

// Minimises `f` from `x0`. `f` is called concurrently from several threads and must be
// thread-safe. Generation g samples its candidates from the stream (seed, g) on the calling
// thread, so the result depends on the seed and not on the thread count.
//   auto r = minimise_cmaes([](std::span<const double> x) { return x[0] * x[0]; }, {1.0});
CmaesResult minimise_cmaes(const std::function<double(std::span<const double>)>& f,
                           std::vector<double> x0, const CmaesOptions& options = {});

}  // namespace ifsfx::collage
