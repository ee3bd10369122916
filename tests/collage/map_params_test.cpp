// SPDX-License-Identifier: Apache-2.0
#include "collage/map_params.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "ifs/rng.h"

namespace ifsfx::collage {
namespace {

void expect_near(const AffineMap& got, const AffineMap& want, double tolerance) {
  const auto g = got.coefficients(), w = want.coefficients();
  for (std::size_t k = 0; k < g.size(); ++k)
    EXPECT_NEAR(g[k], w[k], tolerance) << "coefficient " << k;
}

TEST(map_params, contractive_maps_come_back_from_their_coordinates) {
  // A rotation with unequal scales, a reflection, a shear, a fern-like near-singular map.
  const std::vector<AffineMap> maps = {
      {0.5 * std::cos(0.7), -0.3 * std::sin(0.7), 0.5 * std::sin(0.7), 0.3 * std::cos(0.7), 0.1,
       0.2},
      {-0.4, 0, 0, 0.6, 0.8, 0.1},
      {0.5, 0.2, 0, 0.4, 0.3, 0.3},
      {0.01, 0, 0, 0.16, 0.5, 0},
  };
  MapCoordinates frame{{0.4, 0.6}, 0.97, {}};
  const auto x = to_coordinates(maps, frame);
  ASSERT_EQ(x.size(), 24u);
  EXPECT_EQ(frame.reflected, (std::vector<bool>{false, true, false, false}));
  const auto back = from_coordinates(x, frame);
  for (std::size_t n = 0; n < maps.size(); ++n) expect_near(back[n], maps[n], 1e-9);
}

TEST(map_params, every_coordinate_vector_is_a_contraction_below_the_bound) {
  MapCoordinates frame{{0.5, 0.5}, 0.9, {false, true}};
  Rng rng(7);
  for (int trial = 0; trial < 1000; ++trial) {
    std::vector<double> x(12);
    for (double& v : x) v = 40 * (rng.uniform() - 0.5);
    for (const AffineMap& f : from_coordinates(x, frame)) {
      EXPECT_LT(f.contraction(), 0.9 + 1e-12);
      EXPECT_TRUE(f.finite());
    }
  }
}

TEST(map_params, a_map_that_expands_is_pulled_below_the_bound) {
  MapCoordinates frame{{0.5, 0.5}, 0.9, {}};
  const std::vector<AffineMap> maps = {{1.5, 0, 0, 0.5, 0, 0}};
  const auto back = from_coordinates(to_coordinates(maps, frame), frame);
  EXPECT_NEAR(back[0].contraction(), 0.9 * 0.999, 1e-9);
  EXPECT_NEAR(back[0].d, 0.5, 1e-9) << "the other direction is kept";
  // The centre still goes where it went.
  const Point c = maps[0]({0.5, 0.5}), d = back[0]({0.5, 0.5});
  EXPECT_NEAR(c.x, d.x, 1e-12);
  EXPECT_NEAR(c.y, d.y, 1e-12);
}

}  // namespace
}  // namespace ifsfx::collage
