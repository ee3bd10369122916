// SPDX-License-Identifier: Apache-2.0
// The default colouring IFSs tile the unit square (docs/design.md §3: every source pixel
// reachable), and fit_to_unit_square puts any attractor on it.
#include <gtest/gtest.h>

#include "ifs/preset.h"
#include "ifs/rng.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"

namespace ifsfx {
namespace {

// The pieces g_n([0,1]²) cover the square without overlap: random points lie in exactly one.
void expect_tiling(const Ifs& g) {
  std::vector<AffineMap> inverses;
  for (const auto& m : g.maps) inverses.push_back(*m.inverse());
  Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    const Point p{rng.uniform(), rng.uniform()};
    int inside = 0;
    for (const auto& inv : inverses) {
      const Point q = inv(p);
      inside += q.x > 0 && q.x < 1 && q.y > 0 && q.y < 1;
    }
    ASSERT_EQ(inside, 1) << g.name << " at " << p.x << ", " << p.y;
  }
}

TEST(tiling, default_colourings_tile_the_unit_square) {
  for (std::size_t n : {2, 3, 4, 5, 6, 7, 8, 9, 12, 16}) {
    const Ifs g = default_colouring(n);
    ASSERT_EQ(g.size(), n);
    expect_tiling(g);
    const Box b = attractor_bounds(g);
    EXPECT_NEAR(b.x0, 0, 1e-3) << n;
    EXPECT_NEAR(b.y1, 1, 1e-3) << n;
  }
}

TEST(tiling, four_and_nine_maps_are_square_grids_in_raster_order_from_the_bottom_left) {
  const Ifs g4 = default_colouring(4);
  EXPECT_EQ(g4.maps[1], (AffineMap{0.5, 0, 0, 0.5, 0.5, 0}));
  EXPECT_EQ(g4.maps[2], (AffineMap{0.5, 0, 0, 0.5, 0, 0.5}));
  const Ifs g9 = default_colouring(9);
  const Point p = g9.maps[5]({0, 0});
  EXPECT_NEAR(p.x, 2.0 / 3, 1e-15);
  EXPECT_NEAR(p.y, 1.0 / 3, 1e-15);
}

TEST(tiling, two_and_three_maps_are_swap_maps) {
  // g_k(x, y) = (y, (x + k)/N).
  const Point p = default_colouring(3).maps[2]({0.3, 0.9});
  EXPECT_NEAR(p.x, 0.9, 1e-15);
  EXPECT_NEAR(p.y, (0.3 + 2) / 3, 1e-15);
}

TEST(tiling, default_colourings_are_the_shipped_square_tilings) {
  for (std::size_t n : {2, 3, 4, 9}) {
    const Ifs shipped =
        load_ifs("square-tiling-" + std::to_string(n), {.allow_expansive = true}).ifs;
    const Ifs g = default_colouring(n);
    ASSERT_EQ(g.size(), shipped.size());
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(g.maps[i].coefficients()[k], shipped.maps[i].coefficients()[k], 1e-15)
            << n << " maps, map " << i;
  }
}

TEST(tiling, fit_to_unit_square_stretches_the_attractor_onto_it) {
  Ifs g;
  g.maps = {{0.5, 0, 0, 0.5, 3, 1}, {0.5, 0, 0, 0.5, 4, 1}, {0.5, 0, 0, 0.5, 3, 3}};
  const Box b = attractor_bounds(fit_to_unit_square(g));
  EXPECT_NEAR(b.x0, 0, 1e-6);
  EXPECT_NEAR(b.y0, 0, 1e-6);
  EXPECT_NEAR(b.x1, 1, 1e-6);
  EXPECT_NEAR(b.y1, 1, 1e-6);
}

}  // namespace
}  // namespace ifsfx
