// SPDX-License-Identifier: Apache-2.0
// FractalDB's category search with NumPy's draws: seed 1 finds the categories the reference
// published (data/csv_rate0.2_category1000 of hirokatsukataoka16/FractalDB-Pretrained-ResNet-
// PyTorch, made by its param_search/ifs_search.py), number for number.
#include "fractaldb/search.h"

#include <atomic>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "interrupted.h"

namespace ifsfx::fractaldb {
namespace {

TEST(fractaldb_search, seed_1_finds_the_published_first_categories) {
  std::vector<double> rates;
  std::vector<Category> found;
  search({.categories = 2}, [&](const Category& c, double rate) {
    found.push_back(c);
    rates.push_back(rate);
  });
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].name, "00000");
  EXPECT_EQ(found[1].name, "00001");
  // The first row of 00000.csv and of 00001.csv as published.
  EXPECT_EQ(category_text(found[0]).substr(0, category_text(found[0]).find('\n')),
            "1.724223243171234543e-01,-7.311756060787280020e-01,-2.966728035091932281e-01,"
            "-2.777660563660040438e-01,6.115739281576646480e-01,-2.019335022650967648e-01,"
            "1.414134307013419356e-01");
  EXPECT_EQ(found[0].maps.size(), 5u);
  EXPECT_EQ(found[1].maps[0].a, -1.668389423696419183e-01);
  for (const double rate : rates) EXPECT_GE(rate, 0.2);
}

TEST(fractaldb_search, keeps_what_reaches_the_rate_and_checks_its_options) {
  // Rate 0 keeps every candidate that contracts, so its first is drawn no later than 0.05's.
  std::int64_t tried_strict = 0, tried_loose = 0;
  int kept = 0;
  search(
      {.categories = 2, .rate = 0.05, .points = 20000, .seed = 5},
      [&](const Category&, double rate) {
        EXPECT_GE(rate, 0.05);
        ++kept;
      },
      [&](const SearchProgress& p) { tried_strict = p.tried; });
  search(
      {.categories = 2, .rate = 0.0, .points = 20000, .seed = 5}, [](const Category&, double) {},
      [&](const SearchProgress& p) { tried_loose = p.tried; });
  EXPECT_EQ(kept, 2);
  EXPECT_LE(tried_loose, tried_strict);
  EXPECT_GT(tried_strict, 2);
  EXPECT_THROW(search({.categories = 0}), Error);
  EXPECT_THROW(search({.rate = 1.5}), Error);
  EXPECT_THROW(search({.points = 1}), Error);
  EXPECT_THROW(search({.rate = 0.2, .points = 50000}), Error);  // 50000 points light < 0.191
  std::atomic<bool> stop{true};
  EXPECT_TRUE(testing::interrupted([&] { search({.cancel = CancelToken(&stop)}); }));
}

}  // namespace
}  // namespace ifsfx::fractaldb
