// SPDX-License-Identifier: Apache-2.0
#include "flame/xform_eval.h"

namespace ifsfx::flame {
namespace {

// One pre_ or post_ term: q replaced by w·V(q), or moved by it (Assign::add).
Point chain(const VariationTerm& term, Point q, const AffineMap& pre, Rng& rng) {
  const Variation& v = variation(term.id);
  if (v.kind == VariationKind::flat_3d) return q;
  const Point r = v.function({.p = q, .w = term.weight, .params = term.params, .pre = &pre}, rng);
  return v.assign == Assign::add ? Point{q.x + r.x, q.y + r.y} : r;
}

}  // namespace

Point apply_term(const VariationTerm& term, Point p, const AffineMap& pre, Rng& rng) {
  const Variation& v = variation(term.id);
  return v.function({.p = p, .w = term.weight, .params = term.params, .pre = &pre}, rng);
}

Point apply_xform(const Xform& xf, Point p, Rng& rng) {
  Point q = xf.pre(p);
  for (const VariationTerm& t : xf.pre_variations) q = chain(t, q, xf.pre, rng);
  // The sum; without normal terms, the pre_ terms' point when there are some, else the empty
  // sum (0, 0) — flam3 sums an xform of no variation to the origin, and Ember does too unless
  // it has pre_ terms.
  Point s = xf.pre_variations.empty() ? Point{0, 0} : q;
  if (!xf.variations.empty()) {
    s = {0, 0};
    for (const VariationTerm& t : xf.variations) {
      const Point v = apply_term(t, q, xf.pre, rng);
      s = {s.x + v.x, s.y + v.y};
    }
  }
  // post_ terms before the post-affine map, as Apophysis 7X, JWildfire and Ember apply them.
  for (const VariationTerm& t : xf.post_variations) s = chain(t, s, xf.pre, rng);
  if (xf.post) s = (*xf.post)(s);
  return s;
}

}  // namespace ifsfx::flame
