// SPDX-License-Identifier: Apache-2.0
#include "ifs/affine_map.h"

#include <cmath>

#include <gtest/gtest.h>

namespace ifsfx {
namespace {

TEST(affine_map, contraction_is_the_largest_singular_value) {
  const double t = 0.7, s = 0.6;
  const AffineMap rotation_scale{
      s * std::cos(t), -s * std::sin(t), s * std::sin(t), s * std::cos(t), 1, 2};
  EXPECT_NEAR(rotation_scale.contraction(), 0.6, 1e-12);
  EXPECT_NEAR((AffineMap{0.5, 0, 0, 0.2, 0, 0}).contraction(), 0.5, 1e-12);
  EXPECT_NEAR((AffineMap{0, 0, 0, 0.16, 0, 0}).contraction(), 0.16, 1e-12);  // fern stem
  // A shear: singular values of [[1 1][0 1]] are the golden ratio and its inverse.
  EXPECT_NEAR((AffineMap{1, 1, 0, 1, 0, 0}).contraction(), (1 + std::sqrt(5.0)) / 2, 1e-12);
}

TEST(affine_map, inverse_undoes_the_map_and_singular_maps_have_none) {
  const AffineMap f{0.85, 0.04, -0.04, 0.85, 0, 1.6};
  const auto g = f.inverse();
  ASSERT_TRUE(g.has_value());
  const Point p{0.3, -2.0};
  const Point q = (*g)(f(p));
  EXPECT_NEAR(q.x, p.x, 1e-12);
  EXPECT_NEAR(q.y, p.y, 1e-12);
  EXPECT_FALSE((AffineMap{0, 0, 0, 0.16, 0, 0}).inverse().has_value());
}

TEST(affine_map, compose_applies_the_right_map_first) {
  const AffineMap f{2, 0, 0, 2, 1, 0}, g{0, -1, 1, 0, 0, 0};  // scale+shift, rotation
  const Point p{1, 2};
  const Point a = f.compose(g)(p), b = f(g(p));
  EXPECT_DOUBLE_EQ(a.x, b.x);
  EXPECT_DOUBLE_EQ(a.y, b.y);
}

}  // namespace
}  // namespace ifsfx
