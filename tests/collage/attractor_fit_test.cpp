// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_fit.h"

#include <gtest/gtest.h>

#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

TEST(attractor_fit, cmaes_on_the_attractor_puts_moved_quadrants_back) {
  // The quadrant maps moved and turned: their attractor misses much of the square.
  auto start = testing::quadrant_maps();
  Rng rng(3);
  start = perturbed(start, {0.5, 0.5}, 0.97, 0.3, rng);
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  const double before = loss.terms(start).iou;
  ASSERT_LT(before, 0.85);
  const AttractorRefined r =
      refine_on_attractor(loss, start, {.centre = {0.5, 0.5}, .max_evaluations = 3000});
  EXPECT_GE(loss.terms(r.maps).iou, 0.93) << "from " << before;
  EXPECT_EQ(r.value, loss(r.maps));
  for (const AffineMap& f : r.maps) EXPECT_LT(f.contraction(), 0.97);
}

TEST(attractor_fit, the_same_seed_gives_the_same_maps_for_any_thread_count) {
  auto start = testing::quadrant_maps();
  start[1].e += 0.05;
  const AttractorLoss loss(testing::framed_square(), {.size = 32});
  AttractorRefineOptions o{.centre = {0.5, 0.5}, .max_evaluations = 300, .seed = 9};
  o.threads = 1;
  const auto one = refine_on_attractor(loss, start, o);
  o.threads = 3;
  const auto three = refine_on_attractor(loss, start, o);
  EXPECT_EQ(one.maps, three.maps);
  EXPECT_EQ(one.evaluations, three.evaluations);
}

TEST(attractor_fit, perturbation_moves_every_map_and_keeps_reflections) {
  std::vector<AffineMap> maps = testing::quadrant_maps();
  maps[2].a = -maps[2].a;  // a reflected map
  Rng rng(1);
  const auto moved = perturbed(maps, {0.5, 0.5}, 0.97, 0.1, rng);
  for (std::size_t n = 0; n < maps.size(); ++n) {
    EXPECT_NE(moved[n], maps[n]);
    EXPECT_EQ(moved[n].det() < 0, maps[n].det() < 0) << n;
  }
}

TEST(attractor_fit, metropolis_takes_gains_always_and_losses_by_their_odds) {
  EXPECT_TRUE(metropolis_accepts(-0.1, 0, 0.99));
  EXPECT_TRUE(metropolis_accepts(0.01, 0.01, 0.3));   // exp(−1) ≈ 0.37 > 0.3
  EXPECT_FALSE(metropolis_accepts(0.01, 0.01, 0.4));  // … < 0.4
  EXPECT_FALSE(metropolis_accepts(0.01, 0, 0));       // no temperature, no loss taken
}

}  // namespace
}  // namespace ifsfx::collage
