// SPDX-License-Identifier: Apache-2.0
// The FractalDB reference's chaos game step (ifs_function.calculate), shared by the renderer,
// the search and the contraction estimate: map j is the first whose running sum of p reaches the
// draw r (p summed in file order, as `temp_proba += proba`); none when the sums end below r.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "ifs/affine_map.h"

namespace ifsfx::detail {

struct ReferenceMaps {
  std::vector<AffineMap> maps;
  std::vector<double> cumulative;  // running sums of p

  // The running sums again, padded with +inf to 8 (when there are at most 8): the first j with
  // r ≤ sum_j is the count of sums below r, which needs no branch.
  std::array<double, 8> padded{};
  bool small = false;

  ReferenceMaps(std::vector<AffineMap> m, const std::vector<double>& probabilities)
      : maps(std::move(m)) {
    double sum = 0;
    for (const double p : probabilities) cumulative.push_back(sum += p);
    small = cumulative.size() <= padded.size();
    padded.fill(std::numeric_limits<double>::infinity());
    if (small) std::copy(cumulative.begin(), cumulative.end(), padded.begin());
  }

  // The map the draw r picks, or -1 when r is above every running sum. The sums never decrease
  // (p ≥ 0), so the first j with r ≤ sum_j is the number of sums below r.
  int pick(double r) const {
    std::size_t below = 0;
    if (small) {
      for (std::size_t j = 0; j < padded.size(); ++j) below += padded[j] < r;
    } else {
      while (below < cumulative.size() && cumulative[below] < r) ++below;
    }
    return below < cumulative.size() ? static_cast<int>(below) : -1;
  }
};

}  // namespace ifsfx::detail
