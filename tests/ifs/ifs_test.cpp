// SPDX-License-Identifier: Apache-2.0
#include "ifs/ifs.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx {
namespace {

Ifs fern() {
  Ifs ifs;
  ifs.name = "fern";
  ifs.maps = {{0, 0, 0, 0.16, 0, 0},
              {0.85, 0.04, -0.04, 0.85, 0, 1.6},
              {0.2, -0.26, 0.23, 0.22, 0, 1.6},
              {-0.15, 0.28, 0.26, 0.24, 0, 0.44}};
  return ifs;
}

// validate() must throw Error{kind} with exactly this message.
void expect_error(const Ifs& ifs, ErrorKind kind, const std::string& message,
                  const ValidateOptions& options = {}) {
  try {
    validate(ifs, "test.toml", options);
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind);
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(default_probabilities, are_proportional_to_det_with_a_floor_for_singular_maps) {
  // |det| of the fern's maps: 0, 0.7241, 0.1038, 0.1088; the stem gets the floor 0.01 · 0.7241.
  const auto p = default_probabilities(fern().maps);
  const double sum = 0.007241 + 0.7241 + 0.1038 + 0.1088;
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(p[0], 0.007241 / sum, 1e-12);
  EXPECT_NEAR(p[1], 0.7241 / sum, 1e-12);
  EXPECT_NEAR(p[2], 0.1038 / sum, 1e-12);
  EXPECT_NEAR(p[3], 0.1088 / sum, 1e-12);
}

TEST(default_probabilities, are_uniform_when_every_map_is_singular) {
  const auto p = default_probabilities({{0, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0, 1, 0}});
  EXPECT_DOUBLE_EQ(p[0], 0.5);
  EXPECT_DOUBLE_EQ(p[1], 0.5);
}

TEST(effective_probabilities, normalises_given_ones_and_defaults_the_rest) {
  Ifs ifs = fern();
  ifs.probabilities = {1, 85, 7, 7};
  const auto p = effective_probabilities(ifs);
  EXPECT_DOUBLE_EQ(p[0], 0.01);
  EXPECT_DOUBLE_EQ(p[1], 0.85);
  ifs.probabilities.clear();
  EXPECT_EQ(effective_probabilities(ifs), default_probabilities(ifs.maps));
}

TEST(ifs, contraction_is_the_largest_singular_value_over_its_maps) {
  // 0.85 ± 0.04 i rotation-scale: factor |0.85 + 0.04 i| = sqrt(0.7241).
  EXPECT_NEAR(fern().contraction(), std::sqrt(0.7241), 1e-12);
  Ifs swap;
  swap.maps = {{0, 1, 0.5, 0, 0, 0}, {0.3, 0, 0, 0.3, 0, 0}};  // (y, x/2): singular values 1, 1/2
  EXPECT_NEAR(swap.contraction(), 1.0, 1e-12);
}

TEST(validate, accepts_the_fern) {
  EXPECT_NO_THROW(validate(fern(), "fern"));
}

TEST(validate, rejects_an_ifs_without_maps) {
  expect_error(Ifs{}, ErrorKind::invalid_ifs, "test.toml: an IFS needs at least one map (got 0)");
}

TEST(validate, rejects_nan_and_inf_coefficients) {
  Ifs ifs = fern();
  ifs.maps[2].e = std::numeric_limits<double>::quiet_NaN();
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: map 3: coefficients must be finite numbers (got NaN or inf)");
  ifs = fern();
  ifs.maps[0].b = -std::numeric_limits<double>::infinity();
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: map 1: coefficients must be finite numbers (got NaN or inf)");
}

TEST(validate, rejects_negative_all_zero_and_miscounted_probabilities) {
  Ifs ifs = fern();
  ifs.probabilities = {0.1, 0.9, -0.05, 0.05};
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: map 3: probability must be a finite number ≥ 0 (got -0.05)");
  ifs.probabilities = {0, 0, 0, 0};
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: probabilities: they must not all be zero (got sum 0)");
  ifs.probabilities = {0.5, 0.5};
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: probabilities: one per map is needed (got 2 for 4 maps)");
}

TEST(validate, rejects_colours_of_the_wrong_count) {
  Ifs ifs = fern();
  ifs.colours = {{1, 0, 0}};
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: colours: one per map is needed (got 1 for 4 maps)");
}

TEST(validate, rejects_a_map_of_factor_one_or_more) {
  Ifs ifs = fern();
  ifs.maps[1] = {1.25, 0, 0, 0.5, 0, 0};
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: map 2: contraction factor must be < 1 (got 1.25); "
               "allow_expansive accepts it if the IFS contracts on average");
  ifs.maps[1] = {0, -1, 1, 0, 0, 0};  // a quarter turn: factor exactly 1
  expect_error(ifs, ErrorKind::invalid_ifs,
               "test.toml: map 2: contraction factor must be < 1 (got 1); "
               "allow_expansive accepts it if the IFS contracts on average");
}

TEST(validate, allow_expansive_accepts_maps_that_contract_once_composed) {
  // g_k(x, y) = (y, (x + k)/2): factor 1 each, but g_j ∘ g_k is a similarity of factor 1/2.
  Ifs swap;
  swap.maps = {{0, 1, 0.5, 0, 0, 0}, {0, 1, 0.5, 0, 0, 0.5}};
  expect_error(swap, ErrorKind::invalid_ifs,
               "test.toml: map 1: contraction factor must be < 1 (got 1); "
               "allow_expansive accepts it if the IFS contracts on average");
  EXPECT_NO_THROW(validate(swap, "swap", {.allow_expansive = true}));
}

TEST(validate, allow_expansive_still_rejects_an_ifs_that_does_not_contract_on_average) {
  Ifs ifs;
  // Scalings commute, so every word length gives the mean 0.6 log 2 + 0.4 log 1/2 > 0.
  ifs.maps = {{2, 0, 0, 2, 0, 0}, {0.5, 0, 0, 0.5, 1, 0}};
  ifs.probabilities = {0.6, 0.4};
  try {
    validate(ifs, "test.toml", {.allow_expansive = true});
    ADD_FAILURE() << "an IFS that expands on average was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
    EXPECT_EQ(std::string(e.what()).rfind("test.toml: the IFS must contract on average", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace ifsfx
