// SPDX-License-Identifier: Apache-2.0
#include "farm/segment_join.h"

#include <atomic>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "tests/video/test_frames.h"
#include "video/file_sink.h"
#include "video/file_source.h"

namespace ifsfx::farm {
namespace {

using video::testing::temp_folder;
using video::testing::test_frame;

// A segment as `ifsfx filter --segment` writes it: FFV1 in Matroska on the source's clock.
void write_segment(const std::filesystem::path& path, int first, int frames) {
  const cv::Size size{32, 24};
  video::FileSink sink(path, {.codec = "ffv1",
                              .size = size,
                              .frame_rate = {25, 1},
                              .time_base = {1, 25},
                              .source_clock = true});
  for (int i = first; i < first + frames; ++i)
    sink.write({test_frame(size, i), i, i / 25.0, i, 1, {1, 25}});
  sink.close();
}

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::set<std::string> names_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    names.insert(entry.path().filename().string());
  return names;
}

TEST(join_segments, joins_the_segments_frame_after_frame_into_the_output) {
  const auto dir = temp_folder("join");
  write_segment(dir / "s0.mkv", 0, 4);
  write_segment(dir / "s1.mkv", 4, 3);
  const JoinResult r =
      join_segments({.segments = {dir / "s0.mkv", dir / "s1.mkv"}, .output = dir / "out.mkv"});
  EXPECT_EQ(r.video_packets, 7);
  video::FileSource joined(dir / "out.mkv");
  EXPECT_EQ(joined.count_frames(), 7);
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"s0.mkv", "s1.mkv", "out.mkv"}));
}

TEST(join_segments, refuses_an_output_that_is_a_segment_or_the_input_and_writes_nothing) {
  const auto dir = temp_folder("join-same");
  write_segment(dir / "s0.mkv", 0, 3);
  const std::string segment = contents(dir / "s0.mkv");
  std::ofstream(dir / "in.mp4") << "the input";
  std::filesystem::create_symlink(dir / "in.mp4", dir / "link.mkv");

  try {
    join_segments({.segments = {dir / "s0.mkv"}, .output = dir / "s0.mkv"});
    FAIL() << "a segment was accepted as the output";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument) << e.what();
  }
  JoinOptions through_link{.segments = {dir / "s0.mkv"}, .output = dir / "link.mkv"};
  through_link.policy.inputs.add(dir / "in.mp4");
  try {
    join_segments(through_link);
    FAIL() << "the input, named through a link, was accepted as the output";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument) << e.what();
    EXPECT_NE(std::string(e.what()).find("same file as the input"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contents(dir / "s0.mkv"), segment);
  EXPECT_EQ(contents(dir / "in.mp4"), "the input");
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"s0.mkv", "in.mp4", "link.mkv"}));
}

TEST(join_segments, a_stop_request_leaves_the_existing_output_and_no_temporary_file) {
  const auto dir = temp_folder("join-stop");
  write_segment(dir / "s0.mkv", 0, 3);
  std::ofstream(dir / "out.mkv") << "an earlier result";
  const std::atomic<bool> stop{true};
  JoinOptions options{.segments = {dir / "s0.mkv"}, .output = dir / "out.mkv"};
  options.policy.cancel = CancelToken(&stop);
  try {
    join_segments(options);
    FAIL() << "a stop request was ignored";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::interrupted) << e.what();
  }
  EXPECT_EQ(contents(dir / "out.mkv"), "an earlier result");
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"s0.mkv", "out.mkv"}));
}

}  // namespace
}  // namespace ifsfx::farm
