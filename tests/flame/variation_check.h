// SPDX-License-Identifier: Apache-2.0
// Evaluating one variation of the registry at a point, for the variations' tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flame/variations.h"
#include "ifs/rng.h"

namespace ifsfx::flame::test {

// w·V(x, y) of the variation `name` with `params` (defaults for the missing ones) and the
// xform's pre-affine map `pre`.
inline Point eval(const std::string& name, Point p, double w = 1, std::vector<double> params = {},
                  AffineMap pre = {}, std::uint64_t seed = 1) {
  const Variation* v = find_variation(name);
  EXPECT_NE(v, nullptr) << name;
  if (v == nullptr) return {};
  const std::vector<double> defaults = default_parameters(*v);
  for (std::size_t k = params.size(); k < defaults.size(); ++k) params.push_back(defaults[k]);
  Rng rng(seed);
  return v->function({.p = p, .w = w, .params = params, .pre = &pre}, rng);
}

}  // namespace ifsfx::flame::test

#define EXPECT_POINT_NEAR(got, ex, ey)     \
  do {                                     \
    const ::ifsfx::Point g_ = (got);       \
    EXPECT_NEAR(g_.x, (ex), 1e-9) << #got; \
    EXPECT_NEAR(g_.y, (ey), 1e-9) << #got; \
  } while (0)
