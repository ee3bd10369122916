// SPDX-License-Identifier: Apache-2.0
// Kernel levels: what IFSFX_CPU may ask for, and what is refused (apart from the environment).
#include "ifs/cpu.h"

#include <string>

#include <gtest/gtest.h>

#include "ifs/detail/cpu_level.h"
#include "ifs/error.h"

namespace ifsfx {
namespace {

using detail::select_cpu_level;

std::string refusal(const char* request, const std::vector<CpuLevel>& supported) {
  try {
    select_cpu_level(request, supported);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    return e.what();
  }
  return "accepted";
}

TEST(cpu_level, unset_or_empty_picks_the_best_level_the_cpu_runs) {
  const std::vector<CpuLevel> avx2{CpuLevel::scalar, CpuLevel::avx2};
  EXPECT_EQ(select_cpu_level(nullptr, avx2), CpuLevel::avx2);
  EXPECT_EQ(select_cpu_level("", avx2), CpuLevel::avx2);
  EXPECT_EQ(select_cpu_level(nullptr, {CpuLevel::scalar}), CpuLevel::scalar);
}

TEST(cpu_level, a_named_level_the_cpu_runs_is_taken) {
  const std::vector<CpuLevel> all{CpuLevel::scalar, CpuLevel::avx2, CpuLevel::avx512};
  EXPECT_EQ(select_cpu_level("scalar", all), CpuLevel::scalar);
  EXPECT_EQ(select_cpu_level("avx2", all), CpuLevel::avx2);
  EXPECT_EQ(select_cpu_level("avx512", all), CpuLevel::avx512);
  EXPECT_EQ(select_cpu_level("AVX2", all), CpuLevel::avx2);  // any case
}

TEST(cpu_level, a_level_above_the_cpu_is_refused_naming_what_it_runs) {
  EXPECT_EQ(refusal("avx512", {CpuLevel::scalar, CpuLevel::avx2}),
            "IFSFX_CPU: this CPU runs the kernel levels scalar, avx2 only (got avx512)");
  EXPECT_EQ(refusal("avx2", {CpuLevel::scalar}),
            "IFSFX_CPU: this CPU runs the kernel levels scalar only (got avx2)");
}

TEST(cpu_level, an_unknown_name_is_refused) {
  EXPECT_EQ(refusal("sse4", {CpuLevel::scalar}),
            "IFSFX_CPU: must name a kernel level, scalar, avx2 or avx512 (got 'sse4')");
}

TEST(cpu_level, this_cpu_runs_scalar_first_and_levels_in_order) {
  const auto levels = supported_cpu_levels();
  ASSERT_FALSE(levels.empty());
  EXPECT_EQ(levels.front(), CpuLevel::scalar);
  for (std::size_t i = 1; i < levels.size(); ++i) EXPECT_LT(levels[i - 1], levels[i]);
  EXPECT_EQ(best_cpu_level(), levels.back());
  EXPECT_STREQ(to_string(CpuLevel::avx512), "avx512");
}

}  // namespace
}  // namespace ifsfx
