// SPDX-License-Identifier: Apache-2.0
#include "collage/optimise.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::collage {
namespace {

double sphere(std::span<const double> x) {
  double s = 0;
  for (double v : x) s += (v - 0.3) * (v - 0.3);
  return s;
}

double rosenbrock(std::span<const double> x) {
  return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
}

TEST(cmaes, finds_the_minimum_of_a_sphere) {
  const auto r =
      minimise_cmaes(sphere, std::vector<double>(8, 1.0), {.sigma = 0.5, .max_evaluations = 20000});
  EXPECT_LT(r.value, 1e-10);
  for (double v : r.x) EXPECT_NEAR(v, 0.3, 1e-5);
}

TEST(cmaes, follows_the_rosenbrock_valley) {
  const auto r = minimise_cmaes(rosenbrock, {-1.2, 1.0}, {.sigma = 0.5, .max_evaluations = 20000});
  EXPECT_NEAR(r.x[0], 1, 1e-4);
  EXPECT_NEAR(r.x[1], 1, 1e-4);
}

TEST(cmaes, thread_count_does_not_change_the_result) {
  CmaesOptions o{.sigma = 0.5, .max_evaluations = 3000, .seed = 7};
  o.threads = 1;
  const auto one = minimise_cmaes(rosenbrock, {-1.2, 1.0}, o);
  o.threads = 2;
  const auto two = minimise_cmaes(rosenbrock, {-1.2, 1.0}, o);
  EXPECT_EQ(one.x, two.x);
  EXPECT_EQ(one.evaluations, two.evaluations);
  o.seed = 8;
  const auto other = minimise_cmaes(rosenbrock, {-1.2, 1.0}, o);
  EXPECT_NE(one.x, other.x) << "the seed must matter";
}

TEST(cmaes, budget_and_deadline_stop_the_search) {
  const auto few =
      minimise_cmaes(sphere, std::vector<double>(8, 1.0), {.sigma = 0.5, .max_evaluations = 50});
  EXPECT_LE(few.evaluations, 50);
  CmaesOptions past{.sigma = 0.5};
  past.deadline = std::chrono::steady_clock::now();
  const auto none = minimise_cmaes(sphere, std::vector<double>(8, 1.0), past);
  EXPECT_TRUE(none.deadline_reached);
  EXPECT_EQ(none.evaluations, 1);  // x0 only
  EXPECT_EQ(none.x, std::vector<double>(8, 1.0));
}

TEST(cmaes, bad_options_are_errors) {
  EXPECT_THROW(minimise_cmaes(sphere, {}, {}), Error);
  EXPECT_THROW(minimise_cmaes(sphere, {1.0}, {.sigma = 0}), Error);
}

}  // namespace
}  // namespace ifsfx::collage
