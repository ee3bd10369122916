// SPDX-License-Identifier: Apache-2.0
#include "ifs/image_io.h"

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/image_formats.h"
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

// The fastest PNG (the default: zlib level 1, sub filter) and the smallest (level 9, a filter
// chosen per row) hold the same pixels, and the smallest is the smaller file, on a picture with
// smooth gradients and edges like a render's.
TEST_F(image_io, fastest_and_smallest_png_hold_the_same_pixels) {
  cv::Mat picture;
  cv::resize(gradient(), picture, {640, 480});
  cv::circle(picture, {320, 240}, 150, cv::Scalar(0.9, 0.1, 0.4), -1);
  write_image(dir_ / "fast.png", picture);
  write_image(dir_ / "small.png", picture, {.smallest = true});
  const cv::Mat fast = read_image(dir_ / "fast.png").pixels;
  const cv::Mat small = read_image(dir_ / "small.png").pixels;
  ASSERT_EQ(fast.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(fast, small, cv::NORM_INF), 0);
  EXPECT_LT(fs::file_size(dir_ / "small.png"), fs::file_size(dir_ / "fast.png"));
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

// --bits is checked with the file name, before any work: a long texture burn-in must not end in
// "16 bits per channel needs .png or .tif".
TEST_F(image_io, bits_the_format_cannot_hold_are_refused_before_writing) {
  try {
    check_writable_image(dir_ / "x.jpg", {}, 16);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_NE(std::string(e.what()).find("x.jpg: 16 bits per channel needs .png or .tif (got "
                                         "'.jpg')"),
              std::string::npos)
        << e.what();
  }
  try {
    check_writable_image(dir_ / "x.png", {}, 12);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("bits per channel must be 8 or 16 (got 12)"),
              std::string::npos);
  }
  EXPECT_NO_THROW(check_writable_image(dir_ / "x.png", {}, 16));
  EXPECT_NO_THROW(check_writable_image(dir_ / "x.TIF", {}, 16));
  EXPECT_NO_THROW(check_writable_image(dir_ / "x.exr", {}, 16));  // floats: bits do not apply
  EXPECT_NO_THROW(check_writable_image(dir_ / "x.jpg", {}, 8));
  EXPECT_FALSE(fs::exists(dir_ / "x.jpg"));
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

// The first `fraction` of a file, as a cut download or a full disk leaves it.
fs::path cut(const fs::path& from, const fs::path& to, double fraction = 0.5) {
  const auto keep = static_cast<std::streamsize>(fs::file_size(from) * fraction);
  std::ifstream in(from, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(keep), '\0');
  in.read(bytes.data(), keep);
  std::ofstream(to, std::ios::binary).write(bytes.data(), keep);
  return to;
}

TEST_F(image_io, cut_jpeg_is_refused_not_filled_with_grey) {
  const fs::path photo = "/usr/share/doc/opencv-doc/examples/data/fruits.jpg";
  if (!fs::exists(photo)) GTEST_SKIP() << "opencv-doc sample images not installed";
  EXPECT_NO_THROW(read_image(photo));
  const fs::path half = cut(photo, dir_ / "half.jpg");
  try {
    read_image(half);
    FAIL() << "a cut JPEG was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_EQ(std::string(e.what()), half.string() +
                                         ": corrupt or truncated image (JPEG error: Premature end "
                                         "of JPEG file)");
  }
  // Cut a few bytes from the end only (the end-of-image marker): refused too.
  EXPECT_THROW(read_image(cut(photo, dir_ / "nearly.jpg", 0.999)), Error);
}

TEST_F(image_io, cut_png_is_refused_in_one_line) {
  write_image(dir_ / "whole.png", gradient());
  EXPECT_NO_THROW(read_image(dir_ / "whole.png"));
  const fs::path half = cut(dir_ / "whole.png", dir_ / "half.png");
  try {
    read_image(half);
    FAIL() << "a cut PNG was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_EQ(std::string(e.what()), half.string() + ": corrupt or truncated image (cut short: " +
                                         std::to_string(fs::file_size(half)) +
                                         " bytes, ending inside its IDAT chunk)");
  }
  // Only the IEND chunk missing: the pixels may all be there, but the file is not whole.
  const auto whole = fs::file_size(dir_ / "whole.png");
  try {
    read_image(cut(dir_ / "whole.png", dir_ / "noend.png", (whole - 12.0) / whole));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cut short: " + std::to_string(whole - 12) +
                                         " bytes, ending before its IEND chunk"),
              std::string::npos)
        << e.what();
  }
}

// Half-transparent orange, straight: R 200, G 100, B 50, alpha 128.
cv::Mat half_transparent_orange() {
  return cv::Mat(12, 16, CV_8UC4, cv::Scalar(50, 100, 200, 128));  // BGRA
}

// A file written by OpenImageIO itself with the alpha association given.
void write_with_oiio(const fs::path& path, const cv::Mat& bgra, bool associated) {
  cv::Mat rgba;
  cv::cvtColor(bgra, rgba, cv::COLOR_BGRA2RGBA);
  if (associated) {
    rgba.forEach<cv::Vec4b>([](cv::Vec4b& p, const int*) {
      for (int k = 0; k < 3; ++k)
        p[k] = static_cast<std::uint8_t>(std::lround(p[k] * p[3] / 255.0));
    });
  }
  OIIO::ImageSpec spec(rgba.cols, rgba.rows, 4, OIIO::TypeDesc::UINT8);
  spec.alpha_channel = 3;
  if (!associated) spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgba.data));
  ASSERT_TRUE(out->close());
}

TEST_F(image_io, semi_transparent_pixels_keep_their_colour) {
  const cv::Mat orange = half_transparent_orange();
  // A PNG stores straight colour: read as it is, not multiplied by alpha (darkened).
  write_with_oiio(dir_ / "straight.png", orange, false);
  EXPECT_EQ(cv::norm(read_image(dir_ / "straight.png").pixels, orange, cv::NORM_INF), 0);
  // A TIFF with associated alpha: divided back.
  write_with_oiio(dir_ / "associated.tif", orange, true);
  EXPECT_LE(cv::norm(read_image(dir_ / "associated.tif").pixels, orange, cv::NORM_INF), 1);
  // Written and read back: PNG and TIFF exactly, OpenEXR (stored associated) to float precision.
  for (const char* name : {"out.png", "out.tif"}) {
    write_image(dir_ / name, orange);
    EXPECT_EQ(cv::norm(read_image(dir_ / name).pixels, orange, cv::NORM_INF), 0) << name;
  }
  cv::Mat orange_float;
  orange.convertTo(orange_float, CV_32F, 1 / 255.0);
  write_image(dir_ / "out.exr", orange_float);
  EXPECT_LT(cv::norm(read_image(dir_ / "out.exr").pixels, orange_float, cv::NORM_INF), 1e-3);
}

// The chunk types of a PNG file, in order.
std::vector<std::string> png_chunks(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 8 <= bytes.size();) {
    const auto byte = [&](std::size_t i) {
      return std::size_t{static_cast<unsigned char>(bytes[i])};
    };
    const std::size_t length =
        byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    types.push_back(bytes.substr(at + 4, 4));
    at += 12 + length;
  }
  return types;
}

// The libraries write PNG through OpenImageIO, the light ifsfx through libpng
// (ifs/detail/image_formats.h): every layout ifsfx writes comes back from OpenImageIO's reader
// exactly from both writers, straight alpha included.
TEST_F(image_io, png_holds_grey_bgr_and_bgra_at_8_and_16_bits_exactly) {
  cv::RNG rng(7);
  for (const int channels : {1, 3, 4})
    for (const int bits : {8, 16}) {
      cv::Mat image(37, 53, CV_MAKETYPE(bits == 8 ? CV_8U : CV_16U, channels));
      rng.fill(image, cv::RNG::UNIFORM, 0, bits == 8 ? 256 : 65536);
      const fs::path path =
          dir_ / ("c" + std::to_string(channels) + "_" + std::to_string(bits) + ".png");
      for (const bool smallest : {false, true})
        for (const bool libpng : {false, true}) {
          if (libpng)
            detail::write_png(path, path, image, smallest, {});
          else
            write_image(path, image, {.bits = bits, .smallest = smallest});
          const cv::Mat back = read_image(path).pixels;
          ASSERT_EQ(back.type(), image.type()) << path;
          EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0)
              << path << " smallest " << smallest << " libpng " << libpng;
        }
    }
}

// The light ifsfx's PNG writer (libpng) stores the attributes OpenImageIO writes as text chunks
// that OpenImageIO reads back under the same names: ASCII in tEXt, other text (a preset's "∈") in
// iTXt, which holds UTF-8 (tEXt is Latin-1); the JSON copy is "Description". The same read back
// from the libraries' own write.
TEST_F(image_io, png_metadata_are_text_chunks_with_utf8_kept) {
  const std::string preset = "# x \u2208 [\u22122, 2]\nname = \"fern\"\n";
  const WriteOptions options{.metadata = {{"ifsfx:preset", preset}, {"ifsfx:seed", "42"}}};
  write_image(dir_ / "oiio.png", gradient(), options);
  const std::string description = find(read_image(dir_ / "oiio.png").metadata, "ImageDescription");
  cv::Mat pixels;  // what write_image hands the writer: the file's depth
  gradient().convertTo(pixels, CV_8U, 255);
  detail::write_png(dir_ / "m.png", dir_ / "m.png", pixels, false,
                    {{"Software", "ifsfx"},
                     {"ifsfx:preset", preset},
                     {"ifsfx:seed", "42"},
                     {"ImageDescription", description}});
  EXPECT_EQ(read_image(dir_ / "m.png").metadata, read_image(dir_ / "oiio.png").metadata);
  const ImageFile back = read_image(dir_ / "m.png");
  EXPECT_EQ(find(back.metadata, "ifsfx:preset"), preset);
  EXPECT_EQ(find(back.metadata, "ifsfx:seed"), "42");
  EXPECT_EQ(find(back.metadata, "Software"), "ifsfx");
  EXPECT_EQ(find(back.metadata, "ImageDescription").rfind("ifsfx metadata: {", 0), 0u);
  const std::vector<std::string> chunks = png_chunks(dir_ / "m.png");
  // Software, the seed: tEXt; the preset and the JSON copy of both: iTXt.
  EXPECT_EQ(std::count(chunks.begin(), chunks.end(), "tEXt"), 2);
  EXPECT_EQ(std::count(chunks.begin(), chunks.end(), "iTXt"), 2);
  EXPECT_EQ(chunks.back(), "IEND");
}

// A libpng write that fails part-way (here the file size limit, as a full disk would) is
// Error{io} naming the target, with the system's reason.
TEST_F(image_io, failed_libpng_write_names_the_path_and_the_reason) {
  cv::Mat noise(512, 512, CV_8UC3);
  cv::RNG(3).fill(noise, cv::RNG::UNIFORM, 0, 256);  // incompressible: ~768 KB
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 64 * 1024;
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);  // EFBIG instead of the signal
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  ErrorKind kind = ErrorKind::parse;
  try {
    detail::write_png(dir_ / "big.png", dir_ / "big.png", noise, false, {});
  } catch (const Error& e) {
    message = e.what();
    kind = e.kind();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  EXPECT_EQ(kind, ErrorKind::io);
  EXPECT_EQ(message, (dir_ / "big.png").string() + ": cannot write (File too large)");
}

}  // namespace
}  // namespace ifsfx
