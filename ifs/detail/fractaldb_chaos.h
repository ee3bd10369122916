// SPDX-License-Identifier: Apache-2.0
// The FractalDB reference's chaos game step (ifs_function.calculate), shared by the renderer,
// the search and the contraction estimate: map j is the first whose running sum of p reaches the
// draw r (p summed in file order, as `temp_proba += proba`); none when the sums end below r.
#pragma once

#include <vector>

#include "ifs/affine_map.h"

namespace ifsfx::detail {

struct ReferenceMaps {
  std::vector<AffineMap> maps;
  std::vector<double> cumulative;  // running sums of p

  ReferenceMaps(std::vector<AffineMap> m, const std::vector<double>& probabilities)
      : maps(std::move(m)) {
    double sum = 0;
    for (const double p : probabilities) cumulative.push_back(sum += p);
  }

  // The map the draw r picks, or -1 when r is above every running sum.
  int pick(double r) const {
    for (std::size_t j = 0; j < cumulative.size(); ++j)
      if (r <= cumulative[j]) return static_cast<int>(j);
    return -1;
  }
};

}  // namespace ifsfx::detail
