// SPDX-License-Identifier: Apache-2.0
// How a flame's orbit picks its next xform: by the xforms' weights, or after xform i by the weights
// times row i of the xaos matrix (`chaos`). The renderer (flame/render.h) and the chaos game of
// the paper's modes (flame/flame_chaos.h) pick alike.
//
//   const std::vector<MapPicker> pick = xform_pickers(flame, false);
//   const std::uint32_t next = pick[pick.size() > 1 ? 1 + last : 0](rng.next());
#pragma once

#include <vector>

#include "flame/flame.h"
#include "ifs/rng.h"

namespace ifsfx::flame {

// [0] picks by the weights alone; without xaos (every chaos entry 1) that is all. With xaos,
// [1 + i] picks after xform i by weight × chaos row i, a row of zeros falling back to the
// weights. `normalised`: the weights divided by their sum first, as effective_probabilities
// divides an IFS's, so that an affine flame's table is its IFS's to the bit.
std::vector<MapPicker> xform_pickers(const Flame& flame, bool normalised);

}  // namespace ifsfx::flame
