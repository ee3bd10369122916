// SPDX-License-Identifier: Apache-2.0
// Metadata text is made valid UTF-8 whatever bytes it came from (issue 12): Latin-1 is read as
// Latin-1, valid UTF-8 is kept byte for byte.
#include "ifs/utf8.h"

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/image_io.h"

namespace ifsfx {
namespace {

TEST(valid_utf8, keeps_valid_text_unchanged) {
  const std::vector<std::string> texts{"",
                                       "fern",
                                       "caf\xc3\xa9",
                                       "\xe2\x82\xac 5",
                                       "\xf0\x9f\x8c\xbf",
                                       std::string("nul\0inside", 10)};
  for (const std::string& text : texts) EXPECT_EQ(valid_utf8(text), text);
}

TEST(valid_utf8, reads_stray_bytes_as_latin1) {
  EXPECT_EQ(valid_utf8("caf\xe9"), "caf\xc3\xa9");                    // é
  EXPECT_EQ(valid_utf8("\xff"), "\xc3\xbf");                          // ÿ
  EXPECT_EQ(valid_utf8("\x80\x81"), "\xc2\x80\xc2\x81");              // lone continuation bytes
  EXPECT_EQ(valid_utf8("\xc3"), "\xc3\x83");                          // a sequence cut short
  EXPECT_EQ(valid_utf8("\xc0\xaf"), "\xc3\x80\xc2\xaf");              // overlong '/'
  EXPECT_EQ(valid_utf8("\xed\xa0\x80"), "\xc3\xad\xc2\xa0\xc2\x80");  // a UTF-16 surrogate
  EXPECT_EQ(valid_utf8("\xf4\x90\x80\x80"), "\xc3\xb4\xc2\x90\xc2\x80\xc2\x80");  // > U+10FFFF
}

TEST(valid_utf8, makes_any_bytes_valid) {
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  const std::string once = valid_utf8(all);
  EXPECT_EQ(valid_utf8(once), once);  // valid, so unchanged the second time
}

// A Fractint comment or a file name in Latin-1 must not fail the write of an image
// ("internal error: invalid UTF-8 byte" from the JSON of the metadata).
TEST(valid_utf8, metadata_with_latin1_bytes_is_written_and_read_back) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("ifsfx-utf8-metadata-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (const char* ext : {".png", ".tif", ".jpg", ".exr"}) {
    const auto path = dir / (std::string("caf\xe9") + ext);
    write_image(path, cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(100)),
                {.metadata = {{"ifsfx:preset", "fern { ; Barnsley's foug\xe8re"},
                              {"ifsfx:preset_name", "caf\xe9"}}});
    const ImageFile back = read_image(path);
    std::string preset;
    for (const auto& [key, value] : back.metadata)
      if (key == "ifsfx:preset") preset = value;
    EXPECT_EQ(preset, "fern { ; Barnsley's foug\xc3\xa8re") << ext;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ifsfx
