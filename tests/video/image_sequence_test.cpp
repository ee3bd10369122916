// SPDX-License-Identifier: Apache-2.0
#include "video/image_sequence.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "tests/video/test_frames.h"

namespace ifsfx::video {
namespace {

using testing::temp_folder;
using testing::test_frame;

TEST(image_sequence, pattern_numbers_frames) {
  EXPECT_EQ(sequence_path("frame_%04d.png", 7), "frame_0007.png");
  EXPECT_EQ(sequence_path("dir/f%d.tif", 123), "dir/f123.tif");
  EXPECT_TRUE(is_sequence_pattern("frame_%04d.png"));
  EXPECT_FALSE(is_sequence_pattern("movie.mp4"));
  EXPECT_FALSE(is_sequence_pattern("frame_%s.png"));
  EXPECT_FALSE(is_sequence_pattern("f_%d_%d.png"));
  try {
    sequence_path("frame_%x.png", 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_STREQ(e.what(), "frame_%x.png: an image sequence needs one %d or %0Nd and no other '%'");
  }
}

TEST(image_sequence, written_frames_read_back_unchanged) {
  const auto dir = temp_folder("sequence");
  const std::string pattern = (dir / "frame_%04d.png").string();
  const cv::Size size{40, 30};
  {
    ImageSequenceSink sink(pattern);
    for (int i = 0; i < 5; ++i) sink.write({test_frame(size, i), i, 0});
    sink.close();
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_0000.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_0004.png"));
  ImageSequenceSource source(pattern, {.fps = 10});
  EXPECT_EQ(source.frame_count(), 5);
  EXPECT_EQ(source.size(), size);
  int n = 0;
  while (auto f = source.read()) {
    EXPECT_EQ(f->index, n);
    EXPECT_DOUBLE_EQ(f->timestamp, n / 10.0);
    EXPECT_EQ(cv::norm(f->image, test_frame(size, n), cv::NORM_INF), 0.0);
    ++n;
  }
  EXPECT_EQ(n, 5);

  // Skipped frames are not read; the next read is the frame at that place.
  ImageSequenceSource later(pattern, {.fps = 10});
  ASSERT_TRUE(later.skip());
  ASSERT_TRUE(later.skip());
  const auto third = later.read();
  ASSERT_TRUE(third);
  EXPECT_EQ(third->index, 2);
  EXPECT_EQ(cv::norm(third->image, test_frame(size, 2), cv::NORM_INF), 0.0);
  EXPECT_TRUE(later.skip());
  EXPECT_TRUE(later.skip());
  EXPECT_FALSE(later.skip());
}

TEST(image_sequence, missing_sequence_is_not_found) {
  const auto dir = temp_folder("nosequence");
  try {
    ImageSequenceSource source((dir / "f_%03d.png").string());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
  }
}

// frame_0001, frame_0002, frame_0004: the third file is lost, not the end of the sequence.
void write_numbers(const std::filesystem::path& dir, std::initializer_list<int> numbers) {
  for (int n : numbers)
    write_image(sequence_path((dir / "frame_%04d.png").string(), n), test_frame({20, 10}, n));
}

TEST(image_sequence, gap_is_an_error_naming_the_missing_file) {
  const auto dir = temp_folder("gap");
  write_numbers(dir, {1, 2, 4, 5});
  const std::string pattern = (dir / "frame_%04d.png").string();
  try {
    ImageSequenceSource source(pattern);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_EQ(std::string(e.what()),
              (dir / "frame_0003.png").string() + ": missing from the sequence " + pattern +
                  " (1 file missing between frame_0001.png and frame_0005.png; skip_gaps goes "
                  "on without it)");
  }
  write_numbers(dir, {9});  // 6, 7, 8 missing too
  try {
    ImageSequenceSource source(pattern);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("frame_0003.png: missing from the sequence"),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(4 files missing between frame_0001.png and "
                                         "frame_0009.png; skip_gaps goes on without them)"),
              std::string::npos)
        << e.what();
  }
}

TEST(image_sequence, skipping_gaps_keeps_each_file_at_its_time) {
  const auto dir = temp_folder("skipgap");
  write_numbers(dir, {1, 2, 4, 7});
  // Files that only look alike are not frames: another width, another name.
  write_image(dir / "frame_003.png", test_frame({20, 10}, 3));
  std::filesystem::copy_file(dir / "frame_003.png", dir / "frame_0003.png.bak");
  ImageSequenceSource source((dir / "frame_%04d.png").string(), {.fps = 10, .skip_gaps = true});
  EXPECT_EQ(source.frame_count(), 4);
  EXPECT_EQ(source.time_base().num, 1);
  EXPECT_EQ(source.time_base().den, 10);
  const std::int64_t numbers[] = {1, 2, 4, 7};
  const std::int64_t durations[] = {1, 2, 3, 1};
  int n = 0;
  while (auto f = source.read()) {
    ASSERT_LT(n, 4);
    EXPECT_EQ(f->index, n);
    EXPECT_EQ(f->pts, numbers[n] - 1);
    EXPECT_EQ(f->duration, durations[n]);
    EXPECT_DOUBLE_EQ(f->timestamp, (numbers[n] - 1) / 10.0);
    EXPECT_EQ(cv::norm(f->image, test_frame({20, 10}, numbers[n]), cv::NORM_INF), 0.0);
    ++n;
  }
  EXPECT_EQ(n, 4);
}

TEST(image_sequence, unwritable_folder_fails_before_any_frame) {
  EXPECT_THROW(ImageSequenceSink("/nonexistent/folder/f_%04d.png"), Error);
}

// The frames of a sequence appear together when it is complete; a run that fails or is stopped
// leaves every existing frame file as it was and no temporary file.
TEST(image_sequence, frames_are_put_in_place_only_when_the_sequence_is_complete) {
  const auto dir = temp_folder("staged");
  const std::string pattern = (dir / "f_%02d.png").string();
  const cv::Size size{8, 6};
  {
    ImageSequenceSink sink(pattern);
    for (int i = 0; i < 3; ++i) sink.write({test_frame(size, i), i, 0});
    sink.close();
  }
  const auto first = read_image(dir / "f_01.png").pixels;
  {
    ImageSequenceSink sink(pattern);
    for (int i = 10; i < 14; ++i) sink.write({test_frame(size, i), i, 0});
    EXPECT_FALSE(std::filesystem::exists(dir / "f_03.png"));
    EXPECT_TRUE(sink.abandon().empty());
  }
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"f_00.png", "f_01.png", "f_02.png"}));
  EXPECT_EQ(cv::norm(read_image(dir / "f_01.png").pixels, first, cv::NORM_INF), 0.0);
}

// A frame file of the output pattern that is an input is refused before any work: an input
// sequence written into the same pattern spelt otherwise.
TEST(image_sequence, a_frame_file_that_is_an_input_is_refused) {
  const auto dir = temp_folder("overlap");
  const std::string pattern = (dir / "in_%04d.png").string();
  {
    ImageSequenceSink sink(pattern, {.first = 1});
    for (int i = 0; i < 4; ++i) sink.write({test_frame({8, 8}, i), i, 0});
    sink.close();
  }
  ImageSequenceSource source(pattern);
  OutputOptions output;
  for (const auto& file : source.files()) output.inputs.add(file);
  EXPECT_EQ(source.files().size(), 4u);
  const std::string same = (dir / "." / "in_%04d.png").string();
  try {
    ImageSequenceSink sink(same, {.expected = 4, .output = output});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("in_0001.png: is the same file as the input"),
              std::string::npos)
        << e.what();
  }
  // Without the expected count, the first overlapping frame is refused when it comes.
  ImageSequenceSink sink(same, {.output = output});
  sink.write({test_frame({8, 8}, 0), 0, 0});  // in_0000.png: not an input
  EXPECT_THROW(sink.write({test_frame({8, 8}, 1), 1, 0}), Error);
}

TEST(image_sequence, output_names_with_a_stray_percent_are_refused) {
  for (const char* name : {"x_%99999999999d.png", "x_%d%d.png", "x_%5d.png", "x%.png"}) {
    try {
      check_output_name(name);
      ADD_FAILURE() << name;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::parse);
      EXPECT_EQ(std::string(e.what()).rfind("-o: an image sequence pattern holds one %d", 0), 0u);
    }
  }
  EXPECT_NO_THROW(check_output_name("x_%04d.png"));
  EXPECT_NO_THROW(check_output_name("plain.mp4"));
}

}  // namespace
}  // namespace ifsfx::video
