// SPDX-License-Identifier: Apache-2.0
// The superIFS model: validation in the manner of validate(Ifs), probabilities, burn-in length.
#include "superifs/superifs.h"

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "superifs_fixtures.h"

namespace ifsfx {
namespace {

using testing::paper_fig4;

void expect_invalid(const SuperIfs& s, const std::string& message) {
  try {
    validate(s, "test");
    ADD_FAILURE() << "accepted, expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(superifs, paper_fig4_is_valid_with_the_largest_factor_one_half) {
  const SuperIfs s = paper_fig4();
  EXPECT_NO_THROW(validate(s, "fig4"));
  EXPECT_DOUBLE_EQ(s.contraction(), 0.5);
  EXPECT_EQ(s.size(), 2u);
  EXPECT_EQ(s.maps(), 3u);
  EXPECT_EQ(union_ifs(s).size(), 6u);
}

TEST(superifs, validation_names_the_culprit) {
  SuperIfs s = paper_fig4();
  s.ifs[1].maps.pop_back();
  expect_invalid(s, "test: IFS 2: every IFS needs the same number of maps as IFS 1 (got 2 for 3)");
  s = paper_fig4();
  s.ifs[0].maps[2].a = 1.2;
  expect_invalid(s,
                 "test: IFS 1: map 3: contraction factor must be < 1 (got 1.2); "
                 "allow_expansive accepts it if the IFS contracts on average");
  s = paper_fig4();
  s.ifs[1].maps[0] = {0.3, 0.3, 0.3, 0.3, 0, 0};
  expect_invalid(s,
                 "test: IFS 2 map 1: must be invertible, the V-variable raster inverts every "
                 "map (got det 0)");
  s = paper_fig4();
  s.probabilities = {1, -1};
  expect_invalid(s, "test: IFS 2: probability must be a finite number ≥ 0 (got -1)");
  s.probabilities = {0, 0};
  expect_invalid(s, "test: probabilities: they must not all be zero (got sum 0)");
  s.probabilities = {1};
  expect_invalid(s, "test: probabilities: one per IFS is needed (got 1 for 2 IFSs)");
  s = paper_fig4();
  s.colouring = {Ifs{}, Ifs{}, Ifs{}};
  expect_invalid(s, "test: colouring: give one IFS for all or one per IFS (got 3 for 2 IFSs)");
  s = paper_fig4();
  s.view = Box{0, 0, 0, 1};
  expect_invalid(s, "test: view: must be x0, y0, x1, y1 with x0 < x1 and y0 < y1 (got 0, 0, 0, 1)");
  expect_invalid(SuperIfs{}, "test: a superIFS needs at least one IFS (got 0)");
}

TEST(superifs, default_probabilities_are_uniform) {
  const auto p = effective_probabilities(paper_fig4());
  EXPECT_EQ(p, (std::vector<double>{0.5, 0.5}));
}

TEST(superifs, default_steps_bring_the_largest_factor_below_an_eighth_of_a_pixel) {
  const SuperIfs s = paper_fig4();
  // 2^-14 · 1024 = 1/16 < 1/8 but 2^-13 · 1024 = 1/8.
  EXPECT_EQ(default_steps(s, {1024, 512}), 14);
  EXPECT_EQ(default_steps(s, {1000, 2048}), 15);
}

TEST(superifs, default_colouring_has_m_maps_for_every_n) {
  const SuperIfs s = paper_fig4();
  EXPECT_EQ(colouring_ifs(s, 0).size(), 3u);
  EXPECT_EQ(colouring_ifs(s, 1).maps, colouring_ifs(s, 0).maps);
  // The default strip tiling has factor 1 a map but 1/3 in pairs: 1/√3 a step.
  EXPECT_NEAR(colouring_contraction(s), 1 / std::sqrt(3.0), 1e-9);
}

}  // namespace
}  // namespace ifsfx
