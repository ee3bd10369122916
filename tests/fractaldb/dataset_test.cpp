// SPDX-License-Identifier: Apache-2.0
// A FractalDB dataset folder: the reference's layout, the same bytes for any thread count, whole
// files only after a stop, and a rerun that writes only what is missing.
#include "fractaldb/dataset.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "interrupted.h"

namespace ifsfx::fractaldb {
namespace {

namespace fs = std::filesystem;

class fractaldb_dataset : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ifsfx-fractaldb-dataset-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    spec_.categories = {
        {"00001", {{0.5, 0.1, 0, 0.5, 0, 0}, {0.4, 0, 0.2, 0.5, 0.5, 0.3}}, {0.4, 0.6}},
        {"00000",
         {{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 0.5, 0}, {0.5, 0, 0, 0.5, 0, 0.5}},
         {0.3, 0.3, 0.4}}};
    spec_.weights = {{1, 1, 1, 1, 1, 1}, {0.8, 1, 1, 1, 1, 1}, {1, 1, 1, 1.2, 1, 1}};
    spec_.settings = {.size = {64, 48}, .padding = {3, 3}, .iterations = 4000};
    spec_.instances = 2;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Every file under `folder` by its relative path, with its bytes.
  static std::map<std::string, std::string> files(const fs::path& folder) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(folder))
      if (e.is_regular_file()) {
        std::ifstream in(e.path(), std::ios::binary);
        out[fs::relative(e.path(), folder).string()] = {std::istreambuf_iterator<char>(in), {}};
      }
    return out;
  }

  fs::path dir_;
  DatasetSpec spec_;
};

TEST_F(fractaldb_dataset, writes_every_image_under_its_reference_name) {
  const DatasetStats stats = write_dataset(spec_, dir_ / "db");
  EXPECT_EQ(stats.written, 2 * 3 * 2 * 4);
  EXPECT_EQ(stats.skipped, 0);
  const auto written = files(dir_ / "db");
  ASSERT_EQ(written.size(), 48u);
  EXPECT_TRUE(written.contains("00000/00000_02_count_1_flip3.png"));
  EXPECT_TRUE(written.contains("00001/00001_00_count_0_flip0.png"));
  // Each file is the picture of its key; the categories were given out of order.
  for (std::int64_t i = 0; i < image_count(spec_); i += 7) {
    const ImageKey key = image_key(spec_, i);
    const cv::Mat canvas = draw(walk(spec_.categories[key.category], spec_.weights[key.weight],
                                     spec_.settings, reference_draws(spec_.settings.iterations)),
                                spec_.settings, mask_seed(spec_, key));
    cv::Mat expected;
    to_image(canvas, key.flip, spec_.settings.draw, false, expected);
    const cv::Mat got = read_image(dir_ / "db" / image_path(spec_, key)).pixels;
    EXPECT_EQ(cv::norm(got, expected, cv::NORM_INF), 0) << image_path(spec_, key);
  }
}

TEST_F(fractaldb_dataset, gives_the_same_bytes_for_any_thread_count) {
  write_dataset(spec_, dir_ / "one", {.threads = 1});
  write_dataset(spec_, dir_ / "two", {.threads = 2});
  write_dataset(spec_, dir_ / "five", {.threads = 5});
  EXPECT_EQ(files(dir_ / "one"), files(dir_ / "two"));
  EXPECT_EQ(files(dir_ / "one"), files(dir_ / "five"));
}

TEST_F(fractaldb_dataset, a_rerun_writes_only_the_missing_images) {
  write_dataset(spec_, dir_ / "db");
  const auto full = files(dir_ / "db");
  fs::remove(dir_ / "db" / "00000/00000_01_count_1_flip2.png");
  fs::remove(dir_ / "db" / "00001/00001_02_count_0_flip0.png");
  fs::remove(dir_ / "db" / "00001/00001_02_count_0_flip1.png");
  const DatasetStats stats = write_dataset(spec_, dir_ / "db", {.threads = 2});
  EXPECT_EQ(stats.written, 3);
  EXPECT_EQ(stats.skipped, 45);
  EXPECT_EQ(files(dir_ / "db"), full);
}

TEST_F(fractaldb_dataset, a_stop_leaves_whole_files_and_the_rerun_completes_them) {
  write_dataset(spec_, dir_ / "full");
  std::atomic<bool> stop{false};
  DatasetOptions options{.threads = 2, .progress_interval = 0};
  options.output.cancel = CancelToken(&stop);
  options.progress = [&](const DatasetProgress& p) {
    if (p.done >= 10) stop = true;
  };
  EXPECT_TRUE(testing::interrupted([&] { write_dataset(spec_, dir_ / "db", options); }));
  const auto partial = files(dir_ / "db");
  EXPECT_GE(partial.size(), 10u);
  EXPECT_LT(partial.size(), 48u);
  const auto full = files(dir_ / "full");
  for (const auto& [name, bytes] : partial) {
    ASSERT_TRUE(full.contains(name)) << name << " (a temporary left?)";
    EXPECT_EQ(bytes, full.at(name)) << name;
  }
  stop = false;
  const DatasetStats stats = write_dataset(spec_, dir_ / "db");
  EXPECT_EQ(stats.written + stats.skipped, 48);
  EXPECT_EQ(files(dir_ / "db"), full);
}

TEST_F(fractaldb_dataset, refuses_bad_specs_before_writing) {
  spec_.weights.clear();
  EXPECT_THROW(write_dataset(spec_, dir_ / "db"), Error);
  EXPECT_FALSE(fs::exists(dir_ / "db"));
}

}  // namespace
}  // namespace ifsfx::fractaldb
