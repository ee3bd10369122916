// SPDX-License-Identifier: Apache-2.0
// Putting searched maps together (issue 15): choose N of a pool of candidate maps so that their
// collage covers L best, then move the maps one at a time. Both work on footprints (collage.h):
// a combination is scored without mapping L again, and a moved map costs one map's image.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "collage/collage.h"
#include "ifs/affine_map.h"
#include "ifs/cancel.h"

namespace ifsfx::collage {

struct SelectOptions {
  // 0: plain greedy. k > 0: each greedy step draws among the k + 1 best additions (a seeded
  // GRASP draw), which gives the next-best combinations for restarts.
  int spread = 0;
  std::uint64_t seed = 1;
  int swap_sweeps = 4;  // sweeps of single swaps (a chosen map for an unchosen one) after it
  // No further swap is tried at or after this time (the greedy choice is always completed).
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  CancelToken cancel;  // polled before every swap; a stop request throws Error{interrupted}
};

// Indices of `n` maps of `pool` (their footprints, from `objective`): greedy additions, each the
// one that lowers the collage objective most, then single swaps while one lowers it. The same
// inputs give the same choice. Throws Error{invalid_argument} when the pool has fewer than n.
std::vector<std::size_t> select_maps(const CollageObjective& objective,
                                     std::span<const Footprint> pool, int n,
                                     const SelectOptions& options = {});

struct DescentOptions {
  // What is minimised: 1 = the collage objective (one step of W; a move costs one footprint);
  // k > 1 = CollageObjective::iterated(maps, k), the IoU of W^k(L), nearer the attractor (a
  // move maps W^k(L) again, k·N footprints' worth).
  int iterations = 1;
  int sweeps = 4;             // passes over all maps
  double linear_step = 0.04;  // first step on a, b, c, d (halved when no move helps)
  double pixel_step = 2;      // first step on e, f, in pixels of the working raster
  int halvings = 5;           // steps are halved this often per map and sweep before moving on
  long max_evaluations = 0;   // moves scored at most (checked per step of 12); 0 = no cap
  int threads = 0;            // the 12 moves of a step are scored in parallel; 0 = all cores
  // No step starts at or after this time. The default never comes.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  CancelToken cancel;  // polled before every step; a stop request throws Error{interrupted}
};

struct DescentResult {
  std::vector<AffineMap> maps;
  double value = 0;               // the criterion's value for `maps`
  long evaluations = 0;           // moves scored
  bool deadline_reached = false;  // stopped by the deadline (not by max_evaluations)
};

// Coordinate descent one map at a time: a compass search moves the map's linear part (about L's
// centroid, so that the piece stays where it is) and its translation ±step, takes the best of
// the 12 moves that lowers the criterion, and halves the steps when none does. Deterministic for
// any thread count (the moves are compared in a fixed order).
DescentResult descend_each_map(const CollageObjective& objective, std::vector<AffineMap> maps,
                               const DescentOptions& options = {});

}  // namespace ifsfx::collage
