// SPDX-License-Identifier: Apache-2.0
// The stages of FitMethod::attractor (issue 32), after the collage search has given its starts.
// Internal to collage/ (fit.cpp).
#pragma once

#include <vector>

#include "collage/fitting.h"
#include "ifs/affine_map.h"

namespace ifsfx::collage::detail {

// Refines the distinct `starts` (best first) on the attractor loss with what is left of the
// budget: each start by CMA-ES on a 32² raster; the best two on 64²; perturb-and-accept escapes
// from the best on 64²; optionally the escapes' best grown again from fewer maps (grow.h,
// FitOptions::grow_share); on the working raster, with a fine raster the distinct best candidates
// each a while and then the best on the fine raster, without one the best of all on the working
// raster's loss; maps re-seeded where the error is (reseed.h, FitOptions::reseed_share); last the
// fine raster's rounds. Every stage's best is judged by the chooser (its rendered attractor
// against L), so the fit is never worse than its starts. Runs are counted on from `run`.
void optimise_attractor(Fitting& fitting, std::vector<std::vector<AffineMap>> starts, int run);

}  // namespace ifsfx::collage::detail
