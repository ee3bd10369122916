// SPDX-License-Identifier: Apache-2.0
#include "video/file_source.h"

#include <fstream>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "tests/video/test_frames.h"
#include "video/file_sink.h"

namespace ifsfx::video {
namespace {

using testing::temp_folder;
using testing::test_frame;

// skip() passes over frames without converting them: what read() gives next is the frame a plain
// read of the whole file gives at that place, index and timestamp included.
TEST(file_source, skipped_frames_leave_the_next_frame_as_a_full_read_gives_it) {
  const auto dir = temp_folder("skip");
  const cv::Size size{64, 48};
  {
    FileSink sink(dir / "a.mkv", {.codec = "ffv1", .size = size, .frame_rate = {25, 1}});
    for (int i = 0; i < 12; ++i) sink.write({test_frame(size, i), i, i / 25.0});
    sink.close();
  }
  std::vector<Frame> all;
  FileSource whole(dir / "a.mkv");
  while (auto f = whole.read()) all.push_back(*f);
  ASSERT_EQ(all.size(), 12u);
  FileSource in(dir / "a.mkv");
  for (int i = 0; i < 7; ++i) ASSERT_TRUE(in.skip()) << i;
  const std::optional<Frame> next = in.read();
  ASSERT_TRUE(next);
  EXPECT_EQ(next->index, 7);
  EXPECT_DOUBLE_EQ(next->timestamp, all[7].timestamp);
  EXPECT_EQ(cv::norm(next->image, all[7].image, cv::NORM_INF), 0);
  for (int i = 8; i < 12; ++i) EXPECT_TRUE(in.skip()) << i;
  EXPECT_FALSE(in.skip());
  EXPECT_FALSE(in.read());
}

TEST(file_source, missing_file_is_not_found) {
  try {
    FileSource in("/nonexistent/clip.mp4");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_STREQ(e.what(), "/nonexistent/clip.mp4: no such file");
  }
}

TEST(file_source, text_file_named_mp4_is_unsupported) {
  const auto dir = temp_folder("text");
  std::ofstream(dir / "notes.mp4") << "these are not the frames you are looking for\n";
  try {
    FileSource in(dir / "notes.mp4");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_NE(std::string(e.what()).find("notes.mp4: not a movie file FFmpeg can read"),
              std::string::npos)
        << e.what();
  }
}

TEST(file_source, truncated_file_gives_its_frames_then_an_error) {
  const auto dir = temp_folder("truncated");
  const cv::Size size{64, 48};
  {
    FileSink sink(dir / "full.avi", {.codec = "ffv1", .size = size});
    for (int i = 0; i < 30; ++i) sink.write({test_frame(size, i), i, i / 25.0});
    sink.close();
  }
  const auto bytes = std::filesystem::file_size(dir / "full.avi");
  std::filesystem::copy_file(dir / "full.avi", dir / "cut.avi");
  std::filesystem::resize_file(dir / "cut.avi", bytes / 2);

  FileSource in(dir / "cut.avi");
  int n = 0;
  try {
    while (auto f = in.read()) {
      EXPECT_EQ(cv::norm(f->image, test_frame(size, n), cv::NORM_INF), 0.0) << "frame " << n;
      ++n;
    }
    FAIL() << "no error after " << n << " frames";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("truncated or corrupt"), std::string::npos) << e.what();
  }
  EXPECT_GT(n, 5);
  EXPECT_LT(n, 30);
}

TEST(file_source, clip_with_gaps_keeps_its_timestamps_and_is_complete) {
  // tree.avi's index skips frames: 68 pictures over 29.6 s at 15 fps (ffprobe -count_frames).
  // Its announced 444 frames are a length, not a count, and the file is not truncated.
  const std::filesystem::path clip = "/usr/share/doc/opencv-doc/examples/data/tree.avi";
  if (!std::filesystem::exists(clip)) GTEST_SKIP() << "opencv-doc sample videos not installed";
  FileSource in(clip);
  EXPECT_EQ(in.frame_count(), 444);
  EXPECT_NEAR(in.fps(), 15.0, 1e-3);
  int n = 0;
  double last = -1;
  while (auto f = in.read()) {
    EXPECT_EQ(f->image.size(), in.size());
    EXPECT_GT(f->timestamp, last);
    last = f->timestamp;
    ++n;
  }
  EXPECT_EQ(n, 68);
  EXPECT_NEAR(last, 29.5335, 1e-3);
}

}  // namespace
}  // namespace ifsfx::video
