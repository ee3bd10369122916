#include "ifs/image_io.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx {
namespace {
namespace fs = std::filesystem;

class image_io : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ifsfx-image-io-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

cv::Mat gradient() {
  cv::Mat image(48, 64, CV_32FC3);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) image.at<cv::Vec3f>(y, x) = {x / 63.0f, y / 47.0f, 0.25f};
  return image;
}

std::string find(const std::vector<std::pair<std::string, std::string>>& metadata,
                 const std::string& key) {
  for (const auto& [k, v] : metadata)
    if (k == key) return v;
  return "<missing>";
}

TEST_F(image_io, metadata_round_trips_through_png_and_exr) {
  const std::string preset = "name = \"fern\"\nmaps = [[0,0,0,0.16,0,0]]\n";
  for (const char* name : {"a.png", "a.exr", "a.tif"}) {
    write_image(dir_ / name, gradient(),
                {.metadata = {{"ifsfx:preset", preset}, {"ifsfx:seed", "42"}}});
    const ImageFile back = read_image(dir_ / name);
    EXPECT_EQ(find(back.metadata, "ifsfx:preset"), preset) << name;
    EXPECT_EQ(find(back.metadata, "ifsfx:seed"), "42") << name;
  }
}

TEST_F(image_io, exr_keeps_floats_and_png16_keeps_16_bits) {
  write_image(dir_ / "f.exr", gradient());
  const cv::Mat exr = read_image(dir_ / "f.exr").pixels;
  ASSERT_EQ(exr.type(), CV_32FC3);
  EXPECT_LT(cv::norm(exr, gradient(), cv::NORM_INF), 1e-6);

  write_image(dir_ / "g.png", gradient(), {.bits = 16});
  const cv::Mat png = read_image(dir_ / "g.png").pixels;
  ASSERT_EQ(png.type(), CV_16UC3);
  // Channel order survives: blue (x/63) stays in channel 0 and red (0.25) in channel 2.
  EXPECT_EQ(png.at<cv::Vec3w>(0, 63)[0], 65535);
  EXPECT_EQ(png.at<cv::Vec3w>(0, 63)[2], 16384);
}

TEST_F(image_io, writes_leave_no_temporary_files) {
  write_image(dir_ / "x.png", gradient());
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename(), "x.png");
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST_F(image_io, unknown_extension_and_missing_folder_are_refused_before_writing) {
  try {
    write_image(dir_ / "x.nope", gradient());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_NE(std::string(e.what()).find("x.nope: no image writer for extension '.nope'"),
              std::string::npos);
  }
  try {
    check_writable_image(dir_ / "missing" / "x.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir_ / "x.nope"));
}

TEST_F(image_io, unreadable_files_name_the_path) {
  try {
    read_image(dir_ / "none.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_NE(std::string(e.what()).find("none.png: no such file"), std::string::npos);
  }
  { std::ofstream(dir_ / "text.png") << "not an image"; }
  try {
    read_image(dir_ / "text.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
  }
}

}  // namespace
}  // namespace ifsfx
