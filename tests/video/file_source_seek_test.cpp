// SPDX-License-Identifier: Apache-2.0
// Exact seeking (FrameSource::seek): for random start frames, what a seeked source gives equals a
// sequential decode byte for byte — index, timestamp and pixels — on clips ffmpeg makes here: H.264
// with B-frames and an audio track, MPEG-4 part 2 with B-frames, FFV1 at a variable rate, and an
// image sequence.
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/video/test_frames.h"
#include "video/file_source.h"
#include "video/image_sequence.h"

namespace ifsfx::video {
namespace {

using testing::temp_folder;

constexpr int frames_made = 90;

// Runs ffmpeg on a lavfi test pattern of `frames_made` frames; false when ffmpeg is missing.
bool make_clip(const std::filesystem::path& out, const std::string& encode) {
  const std::string command = fmt::format(
      "ffmpeg -v error -y -f lavfi -i testsrc2=size=96x64:rate=25 -f lavfi -i "
      "sine=frequency=440:sample_rate=48000 -frames:v {} -shortest {} '{}' </dev/null",
      frames_made, encode, out.string());
  return std::system(command.c_str()) == 0;
}

template <class Open>
void expect_seeks_equal_sequential(const Open& open, int expected_frames) {
  std::vector<Frame> all;
  {
    auto whole = open();
    while (auto f = whole->read()) all.push_back(*f);
  }
  ASSERT_EQ(static_cast<int>(all.size()), expected_frames);
  std::mt19937 rng(16);
  std::vector<std::int64_t> starts{0, 1, static_cast<std::int64_t>(all.size()) - 1};
  std::uniform_int_distribution<std::int64_t> pick(1, static_cast<std::int64_t>(all.size()) - 1);
  for (int i = 0; i < 12; ++i) starts.push_back(pick(rng));
  for (const std::int64_t start : starts) {
    auto in = open();
    ASSERT_TRUE(in->seek(start)) << start;
    for (std::int64_t k = start; k < std::min<std::int64_t>(start + 4, all.size()); ++k) {
      const std::optional<Frame> f = in->read();
      ASSERT_TRUE(f) << "start " << start << " frame " << k;
      const Frame& want = all[static_cast<std::size_t>(k)];
      EXPECT_EQ(f->index, k) << "start " << start;
      EXPECT_EQ(f->pts, want.pts) << "start " << start << " frame " << k;
      EXPECT_EQ(f->timestamp, want.timestamp) << "start " << start << " frame " << k;
      ASSERT_EQ(f->image.size(), want.image.size());
      EXPECT_EQ(cv::norm(f->image, want.image, cv::NORM_INF), 0)
          << "start " << start << " frame " << k;
    }
  }
  // Past the end: nothing to give.
  auto in = open();
  EXPECT_FALSE(in->seek(static_cast<std::int64_t>(all.size()) + 5));
}

void check_movie(const std::string& name, const std::string& encode, int expected_frames) {
  silence_libav_log();  // an open GOP decoded from its start warns of missing references
  const auto dir = temp_folder("seek");
  const auto path = dir / name;
  if (!make_clip(path, encode)) GTEST_SKIP() << "ffmpeg cannot make " << name;
  expect_seeks_equal_sequential([&] { return std::make_unique<FileSource>(path); },
                                expected_frames);
}

TEST(file_source_seek, h264_with_b_frames_and_audio_equals_sequential_decode) {
  check_movie("h264.mp4",
              "-c:v libx264 -bf 3 -g 20 -keyint_min 20 -sc_threshold 0 -pix_fmt yuv420p -c:a aac",
              frames_made);
}

TEST(file_source_seek, h264_open_gop_in_matroska_equals_sequential_decode) {
  check_movie("open_gop.mkv",
              "-c:v libx264 -bf 3 -g 16 -x264-params open-gop=1:keyint=16 -pix_fmt yuv420p -an",
              frames_made);
}

TEST(file_source_seek, mpeg4_with_b_frames_equals_sequential_decode) {
  check_movie("mpeg4.mp4", "-c:v mpeg4 -bf 2 -g 15 -an", frames_made);
  check_movie("mpeg4.avi", "-c:v mpeg4 -g 15 -an", frames_made);
}

// Every third frame after the tenth is dropped with its time kept (ffmpeg reads on until it has
// `frames_made`): frame index and time differ.
TEST(file_source_seek, ffv1_at_a_variable_rate_lands_on_the_frame_by_timestamp) {
  check_movie("vfr.mkv",
              "-vf select='lt(n\\,10)+not(eq(mod(n\\,3)\\,2))' -fps_mode vfr -c:v ffv1 -g 10 -an",
              frames_made);
}

TEST(file_source_seek, image_sequence_equals_sequential_read) {
  const auto dir = temp_folder("seek_sequence");
  const std::string pattern = (dir / "f_%03d.png").string();
  const std::string command = fmt::format(
      "ffmpeg -v error -y -f lavfi -i testsrc2=size=48x32:rate=25 -frames:v 30 '{}' </dev/null",
      pattern);
  if (std::system(command.c_str()) != 0) GTEST_SKIP() << "ffmpeg cannot make the sequence";
  expect_seeks_equal_sequential([&] { return std::make_unique<ImageSequenceSource>(pattern); }, 30);
}

}  // namespace
}  // namespace ifsfx::video
