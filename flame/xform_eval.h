// SPDX-License-Identifier: Apache-2.0
// One step of a flame's chaos game through one xform (Draves & Reckase §3 and §3.1; the pre_ and
// post_ lists as Apophysis 7X, JWildfire and Ember apply them):
//
//   q ← A·p                          the pre-affine map
//   q ← V(q) for each pre_ term      in order; each replaces q (pre_blur adds to it)
//   s ← Σ w_v·V_v(q)                 the normal terms; none at all: s = q
//   s ← P·s                          the post-affine map, when there is one
//   s ← V(s) for each post_ term     in order, like the pre_ ones
//
// and the colour coordinate c ← (1 − s)·c + s·colour (paper §5). Variations that act on z only
// (VariationKind::flat_3d) add nothing to the sum and leave the point alone in the lists.
//
//   Rng rng(stream_seed(seed, chunk));
//   p = apply_xform(flame.xforms[i], p, rng); c = apply_colour(flame.xforms[i], c);
#pragma once

#include "flame/flame.h"
#include "flame/variations.h"
#include "ifs/rng.h"

namespace ifsfx::flame {

// The image of p (flame plane) under xform `xf`. Every term's params must hold one value per
// parameter of its variation (the reader makes them so). Draws from `rng` only for random
// variations. May return a non-finite point; the caller re-seeds such points.
Point apply_xform(const Xform& xf, Point p, Rng& rng);

// The colour coordinate after a step through `xf`: (1 − s)·c + s·colour, s = colour_speed.
inline double apply_colour(const Xform& xf, double c) {
  return (1 - xf.colour_speed) * c + xf.colour_speed * xf.colour;
}

// w·V(p) for one term, V's dependent coefficients read from `pre` (the xform's pre-affine map).
Point apply_term(const VariationTerm& term, Point p, const AffineMap& pre, Rng& rng);

}  // namespace ifsfx::flame
