// SPDX-License-Identifier: Apache-2.0
#include "collage/combine.h"

#include <algorithm>
#include <atomic>

#include <gtest/gtest.h>

#include "collage/collage.h"
#include "ifs/error.h"
#include "tests/collage/test_shapes.h"

namespace ifsfx::collage {
namespace {

using testing::framed_square;
using testing::quadrant_maps;

// The quadrant maps among worse ones — each also shrunk, shifted, and mirrored and moved off its
// quadrant: the kind of pool a search returns.
std::vector<AffineMap> pool_with_distractors() {
  std::vector<AffineMap> pool;
  for (const auto& f : quadrant_maps()) {
    AffineMap shrunk = f, shifted = f;
    shrunk.a *= 0.7, shrunk.d *= 0.7;
    shifted.e += 0.1;
    const AffineMap mirrored{0, f.a, f.d, 0, f.e + 0.06, f.f - 0.03};
    pool.insert(pool.end(), {shrunk, shifted, mirrored});
  }
  const auto exact = quadrant_maps();
  pool.insert(pool.begin() + 5, exact.begin(), exact.end());  // not at the front
  return pool;
}

TEST(combine, selection_picks_the_tiling_out_of_a_pool) {
  const CollageObjective objective(framed_square());
  const auto pool = pool_with_distractors();
  std::vector<Footprint> footprints;
  for (const auto& f : pool) footprints.push_back(objective.footprint(f));
  auto chosen = select_maps(objective, footprints, 4);
  std::vector<AffineMap> maps;
  for (std::size_t i : chosen) maps.push_back(pool[i]);
  for (const auto& f : quadrant_maps())
    EXPECT_NE(std::find(maps.begin(), maps.end(), f), maps.end()) << "a quadrant map is missing";
  EXPECT_THROW(select_maps(objective, footprints, 100), Error) << "more maps than the pool";
}

TEST(combine, footprints_score_a_combination_as_its_maps_do) {
  const CollageObjective objective(framed_square());
  const auto pool = pool_with_distractors();
  const std::vector<AffineMap> some = {pool[0], pool[3], pool[7], pool[12]};
  std::vector<Footprint> parts;
  for (const auto& f : some) parts.push_back(objective.footprint(f));
  std::vector<const Footprint*> pointers;
  for (const auto& p : parts) pointers.push_back(&p);
  const ObjectiveTerms a = objective.terms(some);
  const ObjectiveTerms b = objective.terms(std::span<const Footprint* const>(pointers));
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.collage_iou, b.collage_iou);
}

TEST(combine, descent_brings_moved_maps_back_for_any_thread_count) {
  const CollageObjective objective(framed_square());
  auto moved = quadrant_maps();
  moved[0].e += 0.04;  // 2.5 pixels
  moved[1].a *= 0.85;
  moved[3].b = 0.05;
  DescentOptions o;
  o.threads = 1;
  const DescentResult one = descend_each_map(objective, moved, o);
  o.threads = 3;
  const DescentResult three = descend_each_map(objective, moved, o);
  EXPECT_EQ(one.maps, three.maps);
  EXPECT_EQ(one.value, three.value);
  EXPECT_LT(one.value, objective(moved));
  EXPECT_GE(objective.terms(one.maps).collage_iou, 0.97);
}

TEST(combine, descent_on_the_iterated_collage_keeps_a_tiling) {
  const CollageObjective objective(framed_square());
  DescentOptions o;
  o.iterations = 4;
  o.sweeps = 1;
  const DescentResult r = descend_each_map(objective, quadrant_maps(), o);
  EXPECT_EQ(r.value, 0) << "W^4(L) = L already: nothing to gain";
  EXPECT_EQ(r.maps, quadrant_maps());
}

TEST(combine, descent_stops_at_its_deadline_and_budget) {
  const CollageObjective objective(framed_square());
  auto moved = quadrant_maps();
  moved[0].e += 0.04;
  DescentOptions o;
  o.deadline = std::chrono::steady_clock::now();
  const DescentResult late = descend_each_map(objective, moved, o);
  EXPECT_TRUE(late.deadline_reached);
  EXPECT_EQ(late.evaluations, 0);
  EXPECT_EQ(late.maps, moved);
  DescentOptions small;
  small.max_evaluations = 30;
  const DescentResult capped = descend_each_map(objective, moved, small);
  EXPECT_FALSE(capped.deadline_reached);
  EXPECT_LE(capped.evaluations, 30);
  std::atomic<bool> stop{true};
  DescentOptions stopped;
  stopped.cancel = CancelToken(&stop);
  EXPECT_THROW(descend_each_map(objective, moved, stopped), Error);
}

}  // namespace
}  // namespace ifsfx::collage
