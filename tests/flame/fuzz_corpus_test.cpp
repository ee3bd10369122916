// SPDX-License-Identifier: Apache-2.0
// The flame fuzz harness's checks (tests/fuzz/flame_checks.h) on every seed and every input a
// fuzzer once broke (tests/fuzz/{corpus,regressions}/flame), in the normal builds.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "tests/fuzz/flame_checks.h"

namespace ifsfx {
namespace {
namespace fs = std::filesystem;

TEST(fuzz_corpus, flame_reader_holds_on_every_seed_and_regression) {
  std::size_t n = 0;
  const fs::path root = IFSFX_SOURCE_DIR;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = root / "tests/fuzz" / kind / "flame";
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      EXPECT_NO_THROW(fuzz::flame_xml(bytes)) << entry.path();
      ++n;
    }
  }
  EXPECT_GE(n, 5u);
}

TEST(fuzz_corpus, every_flame_seed_but_the_library_one_is_read) {
  const fs::path dir = fs::path(IFSFX_SOURCE_DIR) / "tests/fuzz/corpus/flame";
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename() == "library_palette.flame") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NO_THROW(flame::parse_flames(bytes, entry.path().string())) << entry.path();
  }
}

}  // namespace
}  // namespace ifsfx
