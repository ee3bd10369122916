// SPDX-License-Identifier: Apache-2.0
// Steal map files: what is saved loads back bit for bit; anything else is refused by name.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/steal_map.h"

namespace ifsfx {
namespace {

namespace fs = std::filesystem;

class steal_map_file : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ifsfx_steal_file_" + std::to_string(getpid()) + "_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

StealMap some_map(cv::Size size) {
  StealMap map;
  map.source_uv = cv::Mat(size, CV_32FC2);
  cv::randu(map.source_uv, 0.0, 1.0);
  map.coverage = cv::Mat(size, CV_8UC1);
  cv::randu(map.coverage, 0, 2);
  map.coverage *= 255;
  return map;
}

ErrorKind load_error(const fs::path& path, std::optional<cv::Size> size, std::string* message) {
  try {
    load_steal_map(path, size);
  } catch (const Error& e) {
    *message = e.what();
    return e.kind();
  }
  ADD_FAILURE() << "no error for " << path;
  return ErrorKind::parse;
}

TEST_F(steal_map_file, saved_map_loads_back_bit_for_bit) {
  const StealMap map = some_map({37, 23});
  save(map, dir_ / "t.stealmap");
  const StealMap back = load_steal_map(dir_ / "t.stealmap", cv::Size(37, 23));
  EXPECT_EQ(cv::norm(map.source_uv, back.source_uv, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(map.coverage, back.coverage, cv::NORM_INF), 0);
  EXPECT_FALSE(fs::exists(dir_ / "t.stealmap.part"));
}

TEST_F(steal_map_file, map_of_another_size_is_refused) {
  save(some_map({8, 4}), dir_ / "t.stealmap");
  std::string message;
  EXPECT_EQ(load_error(dir_ / "t.stealmap", cv::Size(16, 8), &message),
            ErrorKind::invalid_argument);
  EXPECT_EQ(message,
            (dir_ / "t.stealmap").string() + ": the steal map must be 16x8 here (got 8x4)");
}

TEST_F(steal_map_file, map_of_another_version_is_refused) {
  save(some_map({8, 4}), dir_ / "t.stealmap");
  {
    std::fstream f(dir_ / "t.stealmap", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(8);
    const std::uint32_t version = 2;
    f.write(reinterpret_cast<const char*>(&version), sizeof version);
  }
  std::string message;
  EXPECT_EQ(load_error(dir_ / "t.stealmap", std::nullopt, &message), ErrorKind::unsupported);
  EXPECT_EQ(message,
            (dir_ / "t.stealmap").string() + ": steal map version 1 is supported (got version 2)");
}

TEST_F(steal_map_file, truncated_map_is_refused) {
  save(some_map({8, 4}), dir_ / "t.stealmap");
  fs::resize_file(dir_ / "t.stealmap", fs::file_size(dir_ / "t.stealmap") - 1);
  std::string message;
  EXPECT_EQ(load_error(dir_ / "t.stealmap", std::nullopt, &message), ErrorKind::io);
  EXPECT_NE(message.find("truncated or corrupt steal map: a 8x4 map has 312 bytes (got 311)"),
            std::string::npos)
      << message;
}

// Overwrites `bytes` at `offset` of the file.
void poke(const fs::path& path, std::streamoff offset, const void* bytes, std::size_t n) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(offset);
  f.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(n));
}

constexpr std::streamoff kHeader = 24;  // magic, version, width, height, reserved

TEST_F(steal_map_file, a_covered_pixel_that_is_not_a_number_is_refused_by_name) {
  StealMap map = some_map({8, 4});
  map.coverage.setTo(255);
  save(map, dir_ / "t.stealmap");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  poke(dir_ / "t.stealmap", kHeader + (2 * 8 + 5) * 8 + 4, &nan, sizeof nan);  // v of (5, 2)
  std::string message;
  EXPECT_EQ(load_error(dir_ / "t.stealmap", std::nullopt, &message), ErrorKind::io);
  EXPECT_NE(message.find("t.stealmap: corrupt steal map: pixel (5, 2) is covered but its source "
                         "point ("),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("nan) is not a finite number"), std::string::npos) << message;

  const float inf = std::numeric_limits<float>::infinity();
  save(map, dir_ / "t.stealmap");
  poke(dir_ / "t.stealmap", kHeader, &inf, sizeof inf);  // u of (0, 0)
  EXPECT_EQ(load_error(dir_ / "t.stealmap", std::nullopt, &message), ErrorKind::io);
  EXPECT_NE(message.find("pixel (0, 0) is covered but its source point (inf, "), std::string::npos)
      << message;
}

TEST_F(steal_map_file, an_uncovered_pixel_may_hold_anything) {
  StealMap map = some_map({8, 4});
  map.coverage.at<std::uint8_t>(3, 7) = 0;
  save(map, dir_ / "t.stealmap");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  poke(dir_ / "t.stealmap", kHeader + (3 * 8 + 7) * 8, &nan, sizeof nan);
  const StealMap back = load_steal_map(dir_ / "t.stealmap");
  EXPECT_TRUE(std::isnan(back.source_uv.at<cv::Vec2f>(3, 7)[0]));
}

TEST_F(steal_map_file, a_coverage_byte_other_than_0_and_255_is_refused) {
  save(some_map({8, 4}), dir_ / "t.stealmap");
  const std::uint8_t seven = 7;
  poke(dir_ / "t.stealmap", kHeader + 8 * 4 * 8 + 1 * 8 + 6, &seven, 1);  // pixel (6, 1)
  std::string message;
  EXPECT_EQ(load_error(dir_ / "t.stealmap", std::nullopt, &message), ErrorKind::io);
  EXPECT_EQ(message, (dir_ / "t.stealmap").string() +
                         ": corrupt steal map: the coverage of pixel (6, 1) is 7 (0 or 255 only)");
}

TEST_F(steal_map_file, other_files_are_refused) {
  std::ofstream(dir_ / "photo.png") << "not a map at all, but long enough to have a header";
  std::string message;
  EXPECT_EQ(load_error(dir_ / "photo.png", std::nullopt, &message), ErrorKind::unsupported);
  EXPECT_EQ(load_error(dir_ / "missing.stealmap", std::nullopt, &message), ErrorKind::not_found);
}

}  // namespace
}  // namespace ifsfx
