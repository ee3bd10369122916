// SPDX-License-Identifier: Apache-2.0
// FractalDB's category search (param_search/ifs_search.py of the reference generator;
// docs/dataset.md): random IFSs kept when their picture fills enough of the image.
//
// With numpy.random.seed(seed) once, each candidate draws its number of maps (randint(2, 8)),
// each map's a..f (uniform(−1, 1, 6)), takes p = |det| / Σ|det|, and walks `points` points of
// the chaos game on the same global generator (random(points)); its `point_gray` picture at
// 512×512 with padding 6 is kept when its lit pixels are at least `rate` of the image. The draws
// are NumPy's, so the search finds the reference's categories in the reference's order. A
// candidate that the category reader would refuse (one that does not contract on average, whose
// points collapse, so that the reference drops it too) is dropped.
//   for (const auto& c : fractaldb::search({.categories = 10})) ...
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "ifs/cancel.h"
#include "ifs/fractaldb_csv.h"

namespace ifsfx::fractaldb {

struct SearchProgress {
  int found = 0, wanted = 0;
  std::int64_t tried = 0;  // candidates drawn so far
  double seconds = 0;
};

struct SearchOptions {
  int categories = 1000;   // --category: how many to find
  double rate = 0.2;       // --rate: the least filling rate kept, in [0, 1]
  int points = 100000;     // --numof_point: chaos-game points per candidate
  std::uint32_t seed = 1;  // numpy.random.seed
  CancelToken cancel;      // polled per candidate
};

// The filling rate of one IFS as the search measures it: lit pixels of the point_gray picture of
// `points` points at 512×512, padding 6, from `draws`, over 512·512.
double filling_rate(const Category& category, int points, const std::vector<double>& draws);

// Runs the search, calling found(category, filling rate) for each category kept, in order,
// named "00000", "00001", ...; progress (if any) after each candidate. Throws
// Error{invalid_argument} for categories outside 1..1000000, a rate outside [0, 1] or above
// points / 512² (never reached), points outside 2..10^8, and Error{interrupted} on a stop.
void search(const SearchOptions& options,
            const std::function<void(const Category& category, double rate)>& found,
            const std::function<void(const SearchProgress&)>& progress = {});
// The categories found.
std::vector<Category> search(const SearchOptions& options);

}  // namespace ifsfx::fractaldb
