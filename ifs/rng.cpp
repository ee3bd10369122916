// SPDX-License-Identifier: Apache-2.0
#include "ifs/rng.h"

#include <cmath>

namespace ifsfx {

MapPicker::MapPicker(const std::vector<double>& probabilities)
    : n_(probabilities.size()), threshold_(n_), alias_(n_) {
  double sum = 0;
  for (double p : probabilities) sum += p;
  // Vose's construction of the alias table, in long double to keep the thresholds exact.
  std::vector<long double> scaled(n_);
  std::vector<std::uint32_t> small, large;
  for (std::uint32_t i = 0; i < n_; ++i) {
    scaled[i] = static_cast<long double>(probabilities[i]) / sum * static_cast<long double>(n_);
    (scaled[i] < 1 ? small : large).push_back(i);
  }
  const auto to_threshold = [](long double q) {
    const long double t = std::floor(q * 4294967296.0L + 0.5L);
    return t >= 4294967295.0L ? 0xffffffffu : static_cast<std::uint32_t>(t);
  };
  while (!small.empty() && !large.empty()) {
    const std::uint32_t s = small.back(), l = large.back();
    small.pop_back();
    threshold_[s] = to_threshold(scaled[s]);
    alias_[s] = l;
    scaled[l] -= 1 - scaled[s];
    if (scaled[l] < 1) {
      large.pop_back();
      small.push_back(l);
    }
  }
  for (auto i : large) threshold_[i] = 0xffffffffu, alias_[i] = i;
  for (auto i : small) threshold_[i] = 0xffffffffu, alias_[i] = i;  // rounding leftovers
}

}  // namespace ifsfx
