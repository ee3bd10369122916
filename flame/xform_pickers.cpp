// SPDX-License-Identifier: Apache-2.0
#include "flame/xform_pickers.h"

namespace ifsfx::flame {

std::vector<MapPicker> xform_pickers(const Flame& flame, bool normalised) {
  std::vector<double> weights;
  bool xaos = false;
  double total = 0;
  for (const Xform& xf : flame.xforms) {
    weights.push_back(xf.weight);
    total += xf.weight;
    for (double c : xf.chaos) xaos = xaos || c != 1;
  }
  if (normalised)
    for (double& w : weights) w /= total;
  std::vector<MapPicker> out{MapPicker(weights)};
  if (!xaos) return out;
  for (const Xform& from : flame.xforms) {
    std::vector<double> row = weights;
    double sum = 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (j < from.chaos.size()) row[j] *= from.chaos[j];
      sum += row[j];
    }
    out.emplace_back(sum > 0 ? row : weights);
  }
  return out;
}

}  // namespace ifsfx::flame
