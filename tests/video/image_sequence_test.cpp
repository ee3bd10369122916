#include "video/image_sequence.h"

#include <gtest/gtest.h>

#include "ifs/error.h"
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

TEST(image_sequence, unwritable_folder_fails_before_any_frame) {
  EXPECT_THROW(ImageSequenceSink("/nonexistent/folder/f_%04d.png"), Error);
}

}  // namespace
}  // namespace ifsfx::video
