// SPDX-License-Identifier: Apache-2.0
// The variations of fractal flames (Draves & Reckase, appendix: "Catalog of Variations", and the
// later ones of flam3, Apophysis, JWildfire and Ember), in ONE registry that the reader, the
// writer, the renderer, the studio and the tests all consult (OpenImageIO's Filter2D model): a
// variation is a row {name, parameters with defaults, function}; adding one is one row and its
// test (tests/flame/variations_test.cpp).
//
//   const Variation* v = find_variation("julian");
//   Point q = v->function({.p = p, .w = 0.5, .params = term.params, .pre = xf.pre}, rng);
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "ifs/affine_map.h"
#include "ifs/rng.h"

namespace ifsfx::flame {

// What a variation is evaluated at.
struct VariationInput {
  Point p;                         // the point, flame plane: the affine (or previous) result
  double w = 1;                    // the term's weight: the result is w·V(p)
  std::span<const double> params;  // the term's parameter values, in the registry's order
  const AffineMap* pre = nullptr;  // the xform's pre-affine map, ifsfx order (for "dependent"
                                   // variations: popcorn, waves, rings, fan); never null in use
};

// w·V(p). `rng` is the walker's generator, drawn from only by the random variations (blur, noise,
// julia's branch, ...), so a variation that is not random never changes its state.
using VariationFunction = Point (*)(const VariationInput& in, Rng& rng);

struct VariationParameter {
  std::string_view name;  // the attribute's name in files: "julian_power"
  double default_value = 0;
};

enum class VariationKind {
  plain,      // a function of p (and of its parameters) only
  dependent,  // also reads the xform's affine coefficients
  random,     // draws from the walker's Rng
  flat_3d,    // acts on z only (flatten, zscale, ztranslate, ...): the identity's no-op in 2-D
};

// Where a variation may stand in an xform.
enum class VariationPlace {
  any,       // NAME in the sum, pre_NAME before it, post_NAME after it (before the post map)
  pre_only,  // flam3's pre_blur: a name of its own that already says "pre"
};

// How a variation standing in the pre_/post_ lists combines with the point it is given.
enum class Assign {
  replace,  // p ← w·V(p): Apophysis 7X, JWildfire and Ember's rule for pre_ and post_
  add,      // p ← p + w·V(p): the random offsets (pre_blur, blur, gaussian_blur, pie, arch,
            // square, sineblur, blur_circle), as Ember applies them
};

struct Variation {
  std::uint32_t id = 0;  // its index in variations()
  std::string_view name;
  std::span<const VariationParameter> parameters;
  VariationFunction function = nullptr;
  VariationKind kind = VariationKind::plain;
  VariationPlace place = VariationPlace::any;
  Assign assign = Assign::replace;
};

// Every variation, id order (the ids are stable within a build, not across builds: files and
// the studio name variations, never number them).
std::span<const Variation> variations();

// The variation called `name` (exactly as files write it, without a pre_/post_ prefix, but for
// the pre_only ones), or nullptr.
const Variation* find_variation(std::string_view name);

// The variation with this id; id < variations().size().
const Variation& variation(std::uint32_t id);

// The parameter values of a variation at their defaults.
std::vector<double> default_parameters(const Variation& v);

}  // namespace ifsfx::flame
