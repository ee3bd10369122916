// SPDX-License-Identifier: Apache-2.0
// The fuzz harnesses' checks (tests/fuzz/fuzz_checks.h) on every seed and every input a fuzzer once
// broke (tests/fuzz/corpus/<reader>, tests/fuzz/regressions/<reader>, the shipped presets), in
// the normal Release and sanitizer builds: a bug the fuzzers found stays fixed.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz/fuzz_checks.h"

namespace ifsfx {
namespace {
namespace fs = std::filesystem;

// The files of tests/fuzz/{corpus,regressions}/<reader>, and the presets ending in `shipped`.
std::vector<fs::path> inputs(const std::string& reader, const std::string& shipped = {}) {
  std::vector<fs::path> files;
  const fs::path root = IFSFX_SOURCE_DIR;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = root / "tests/fuzz" / kind / reader;
    if (fs::is_directory(dir))
      for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
  }
  if (!shipped.empty())
    for (const auto& entry : fs::directory_iterator(root / "presets")) {
      const std::string name = entry.path().filename().string();
      if (name.ends_with(shipped) && !(shipped == ".toml" && name.ends_with(".super.toml")))
        files.push_back(entry.path());
    }
  return files;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(fuzz_corpus, preset_toml_reader_holds_on_every_seed_and_regression) {
  const auto files = inputs("preset_toml", ".toml");
  EXPECT_GE(files.size(), 10u);
  for (const fs::path& file : files) EXPECT_NO_THROW(fuzz::preset_toml(bytes_of(file))) << file;
}

TEST(fuzz_corpus, fractint_reader_holds_on_every_seed_and_regression) {
  const auto files = inputs("fractint", ".ifs");
  EXPECT_GE(files.size(), 2u);
  for (const fs::path& file : files) EXPECT_NO_THROW(fuzz::fractint(bytes_of(file))) << file;
}

TEST(fuzz_corpus, fractaldb_csv_reader_holds_on_every_seed_and_regression) {
  const auto files = inputs("fractaldb_csv");
  EXPECT_GE(files.size(), 3u);
  for (const fs::path& file : files) EXPECT_NO_THROW(fuzz::fractaldb_csv(bytes_of(file))) << file;
}

TEST(fuzz_corpus, steal_map_reader_holds_on_every_seed_and_regression) {
  const auto files = inputs("steal_map");
  EXPECT_GE(files.size(), 3u);
  const fs::path scratch = fuzz::scratch_file("steal-map-test");
  for (const fs::path& file : files)
    EXPECT_NO_THROW(fuzz::steal_map_file(bytes_of(file), scratch)) << file;
  fs::remove(scratch);
}

}  // namespace
}  // namespace ifsfx
