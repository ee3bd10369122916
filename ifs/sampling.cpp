// SPDX-License-Identifier: Apache-2.0
#include "ifs/sampling.h"

namespace ifsfx {

Viewport framed_viewport(const Ifs& ifs, cv::Size size, const Sampling& sampling) {
  if (sampling.view) return {*sampling.view, size};
  return {fit_view(attractor_bounds(ifs, sampling.seed, sampling.cancel), size, sampling.margin),
          size};
}

}  // namespace ifsfx
