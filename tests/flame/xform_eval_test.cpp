// SPDX-License-Identifier: Apache-2.0
// One xform's step: pre-affine, pre_ terms, the weighted sum, post_ terms, post-affine, in that
// order, and the colour update c ← (1 − s)·c + s·colour.
#include "flame/xform_eval.h"

#include <gtest/gtest.h>

#include "variation_check.h"

namespace ifsfx::flame {
namespace {

VariationTerm term(const char* name, double weight) {
  const Variation* v = find_variation(name);
  return {.id = v->id, .weight = weight, .params = default_parameters(*v)};
}

TEST(xform_eval, flam3_coefs_swap_b_and_c) {
  // coefs="a b c d e f" means x' = a x + c y + e, y' = b x + d y + f
  const AffineMap m = from_flam3_coefs({1, 2, 3, 4, 5, 6});
  EXPECT_POINT_NEAR(m(Point{1, 0}), 1 + 5, 2 + 6);
  EXPECT_POINT_NEAR(m(Point{0, 1}), 3 + 5, 4 + 6);
  EXPECT_EQ(to_flam3_coefs(m), (std::array<double, 6>{1, 2, 3, 4, 5, 6}));
}

TEST(xform_eval, no_variation_sums_to_the_origin_then_the_post_map) {
  // flam3 and Ember: the empty sum is (0, 0), whatever the pre-affine map; the post-affine map
  // then moves it (a constant map).
  Rng rng(1);
  EXPECT_POINT_NEAR(apply_xform(Xform{.pre = {.a = 2, .d = 3, .e = 1}}, {1, 1}, rng), 0, 0);
  const Xform xf{.pre = {.a = 2, .d = 3, .e = 1}, .post = AffineMap{.e = 0.5, .f = -2}};
  EXPECT_POINT_NEAR(apply_xform(xf, {1, 1}, rng), 0.5, -2);
}

TEST(xform_eval, pre_terms_alone_pass_their_point_through) {
  // Ember: with pre_ terms and no normal ones, the pre_ terms' point is the sum.
  // A(1, 1) = (2, 3) + (1, 0) = (3, 3); pre_spherical: (3, 3) / 18.
  const Xform xf{.pre = {.a = 2, .d = 3, .e = 1}, .pre_variations = {term("spherical", 1)}};
  Rng rng(1);
  EXPECT_POINT_NEAR(apply_xform(xf, {1, 1}, rng), 3.0 / 18, 3.0 / 18);
}

TEST(xform_eval, terms_are_summed_with_their_weights) {
  // 0.5·linear + 0.25·spherical at (2, 0): (1, 0) + 0.25·(0.5, 0)
  const Xform xf{.variations = {term("linear", 0.5), term("spherical", 0.25)}};
  Rng rng(1);
  EXPECT_POINT_NEAR(apply_xform(xf, {2, 0}, rng), 1.125, 0);
}

TEST(xform_eval, pre_terms_replace_the_point_before_the_sum_and_post_terms_before_post) {
  // pre: A(p) = p + (1, 0) = (2, 0); pre_spherical: (0.5, 0); sum: 2·linear = (1, 0);
  // post_spherical → (1, 0); post: x' = x + 3 → (4, 0) — the order of Apophysis 7X, JWildfire
  // and Ember (post-affine last; the other order gives (0.25, 0)).
  Xform xf{.pre = {.e = 1},
           .post = AffineMap{.e = 3},
           .pre_variations = {term("spherical", 1)},
           .variations = {term("linear", 2)},
           .post_variations = {term("spherical", 1)}};
  Rng rng(1);
  EXPECT_POINT_NEAR(apply_xform(xf, {1, 0}, rng), 4, 0);
}

TEST(xform_eval, colour_moves_towards_the_xform_colour_by_its_speed) {
  const Xform xf{.colour = 1, .colour_speed = 0.25};
  EXPECT_DOUBLE_EQ(apply_colour(xf, 0.2), 0.75 * 0.2 + 0.25);
  EXPECT_DOUBLE_EQ(apply_colour(Xform{.colour = 0.3, .colour_speed = 0}, 0.9), 0.9);
}

}  // namespace
}  // namespace ifsfx::flame
