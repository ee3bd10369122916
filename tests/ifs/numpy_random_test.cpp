// SPDX-License-Identifier: Apache-2.0
// NumPy's legacy generator, draw for draw: the known answers were printed by NumPy 1.24
// (numpy.random.seed(s); random(), randint(2, 8), uniform(-1.0, 1.0, 6)).
#include "ifs/detail/numpy_random.h"

#include <vector>

#include <gtest/gtest.h>

namespace ifsfx {
namespace {

TEST(numpy_random, random_gives_numpys_doubles_for_seed_100) {
  detail::NumpyRandom random(100);
  EXPECT_EQ(random.random(), 0.5434049417909654);
  EXPECT_EQ(random.random(), 0.27836938509379616);
  EXPECT_EQ(random.random(), 0.42451759074913309);
  random.skip_random(100000 - 4);
  EXPECT_EQ(random.random(), 0.03730752162806206);  // random(100000)[99999]
}

TEST(numpy_random, randint_and_uniform_give_numpys_draws_for_seed_1) {
  detail::NumpyRandom random(1);
  EXPECT_EQ(random.randint(2, 8), 7);
  const double expected[] = {0.9943696218777371, 0.8651147186773176,  -0.7437511041412865,
                             0.9980810306482895, -0.5278220460960479, -0.20683854540794777};
  for (const double x : expected) EXPECT_EQ(random.uniform(-1.0, 1.0), x);
}

TEST(numpy_random, randint_rejects_masked_draws_as_numpy_does) {
  detail::NumpyRandom random(7);
  std::vector<std::int64_t> got;
  for (int i = 0; i < 20; ++i) got.push_back(random.randint(2, 8));
  EXPECT_EQ(
      got, (std::vector<std::int64_t>{6, 3, 5, 5, 6, 3, 2, 3, 4, 4, 2, 6, 2, 6, 2, 5, 4, 5, 6, 6}));
}

}  // namespace
}  // namespace ifsfx
