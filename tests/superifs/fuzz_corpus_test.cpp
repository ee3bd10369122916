// SPDX-License-Identifier: Apache-2.0
// The superIFS fuzz harness's check on every seed and every input a fuzzer once broke
// (tests/fuzz/corpus/superifs, tests/fuzz/regressions/superifs, the shipped *.super.toml).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "tests/fuzz/superifs_checks.h"

namespace ifsfx {
namespace {
namespace fs = std::filesystem;

TEST(fuzz_corpus, superifs_reader_holds_on_every_seed_and_regression) {
  const fs::path root = IFSFX_SOURCE_DIR;
  std::vector<fs::path> files;
  for (const fs::path& dir : {root / "tests/fuzz/corpus/superifs",
                              root / "tests/fuzz/regressions/superifs", root / "presets"})
    if (fs::is_directory(dir))
      for (const auto& entry : fs::directory_iterator(dir))
        if (dir != root / "presets" || entry.path().string().ends_with(".super.toml"))
          files.push_back(entry.path());
  EXPECT_GE(files.size(), 5u);
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NO_THROW(fuzz::superifs_toml(text)) << file;
  }
}

}  // namespace
}  // namespace ifsfx
