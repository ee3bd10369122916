// SPDX-License-Identifier: Apache-2.0
// The calling thread's CPU clock, for the plain benchmark programs that print their own tables
// (collage_loss_bench, flame_plot_bench): CPU time, which other processes on a shared machine move
// less than the wall clock.
#pragma once

#include <algorithm>
#include <ctime>

namespace ifsfx::bench {

inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Seconds of thread CPU per call of f, best of 3 rounds of at least `round` seconds.
template <typename F>
double seconds_per_call(F&& f, double round = 0.2) {
  double best = 1e30;
  for (int k = 0; k < 3; ++k) {
    long calls = 0;
    const double start = thread_seconds();
    double now = start;
    do {
      f();
      ++calls;
      now = thread_seconds();
    } while (now - start < round);
    best = std::min(best, (now - start) / static_cast<double>(calls));
  }
  return best;
}

}  // namespace ifsfx::bench
