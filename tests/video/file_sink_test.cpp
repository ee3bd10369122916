// SPDX-License-Identifier: Apache-2.0
#include "video/file_sink.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "tests/video/test_frames.h"
#include "video/file_source.h"

namespace ifsfx::video {
namespace {

using testing::temp_folder;
using testing::test_frame;

void write_movie(const std::filesystem::path& path, const std::string& codec, cv::Size size,
                 int frames) {
  FileSink sink(path, {.codec = codec, .size = size, .frame_rate = {25, 1}});
  for (int i = 0; i < frames; ++i) sink.write({test_frame(size, i), i, i / 25.0});
  sink.close();
}

TEST(file_sink, ffv1_round_trip_is_lossless) {
  const auto dir = temp_folder("ffv1");
  const cv::Size size{64, 48};
  write_movie(dir / "a.mkv", "ffv1", size, 12);
  FileSource in(dir / "a.mkv");
  EXPECT_EQ(in.size(), size);
  EXPECT_EQ(in.frame_rate().num, 25);
  EXPECT_EQ(in.frame_rate().den, 1);
  int n = 0;
  while (auto f = in.read()) {
    EXPECT_EQ(f->index, n);
    EXPECT_NEAR(f->timestamp, n / 25.0, 1e-3);
    EXPECT_EQ(cv::norm(f->image, test_frame(size, n), cv::NORM_INF), 0.0) << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, 12);
}

TEST(file_sink, h264_keeps_every_frame_close_to_its_source) {
  const auto dir = temp_folder("h264");
  const cv::Size size{96, 64};
  write_movie(dir / "a.mp4", "", size, 20);
  FileSource in(dir / "a.mp4");
  int n = 0;
  while (auto f = in.read()) {
    EXPECT_GT(cv::PSNR(f->image, test_frame(size, n)), 28.0) << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, 20);
}

// MJPEG codes full-range YUV (FFmpeg's encoder refuses limited range): the levels must come back
// as they went in, not stretched or squeezed by a range mix-up.
TEST(file_sink, mjpeg_keeps_the_levels_of_its_source) {
  const auto dir = temp_folder("mjpeg");
  const cv::Size size{96, 64};
  write_movie(dir / "a.avi", "mjpeg", size, 10);
  FileSource in(dir / "a.avi");
  int n = 0;
  while (auto f = in.read()) {
    const cv::Mat source = test_frame(size, n);
    EXPECT_GT(cv::PSNR(f->image, source), 28.0) << "frame " << n;
    const cv::Scalar got = cv::mean(f->image), want = cv::mean(source);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], want[c], 3.0) << "frame " << n << " channel " << c;
    ++n;
  }
  EXPECT_EQ(n, 10);
}

TEST(file_sink, default_encoder_follows_the_container_like_ffmpeg) {
  EXPECT_EQ(resolve_encoder("x.mp4", ""), "libx264");
  EXPECT_EQ(resolve_encoder("x.mkv", ""), "libx264");
  EXPECT_EQ(resolve_encoder("x.avi", ""), "mpeg4");
  EXPECT_EQ(resolve_encoder("x.mkv", "ffv1"), "ffv1");
  EXPECT_EQ(resolve_encoder("x.mp4", "h264"), "libx264");
}

TEST(file_sink, unknown_codec_and_container_are_refused) {
  try {
    resolve_encoder("x.mp4", "nosuchcodec");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_STREQ(e.what(),
                 "codec: unknown video encoder (got 'nosuchcodec'; `ffmpeg -encoders` lists them)");
  }
  try {
    resolve_encoder("x.qqq", "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
  }
  EXPECT_THROW(resolve_encoder("x.mp4", "aac"), Error);  // an audio encoder
}

TEST(file_sink, unwritable_output_fails_before_any_frame) {
  const auto dir = temp_folder("unwritable");
  try {
    FileSink sink(dir / "missing" / "out.mp4", {.size = {16, 16}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("out.mp4: cannot write"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// The names in a folder, sorted.
std::vector<std::string> names_in(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(file_sink, unfinished_file_never_takes_the_output_name) {
  const auto dir = temp_folder("partial");
  std::ofstream(dir / "out.mkv.part") << "someone else's";
  FileSink sink(dir / "out.mkv", {.codec = "ffv1", .size = {16, 16}});
  sink.write({test_frame({16, 16}, 0), 0, 0});
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mkv"));
  const auto during = names_in(dir);  // the movie is written to a hidden temporary file
  ASSERT_EQ(during.size(), 2u);
  EXPECT_EQ(during[0].rfind(".out.mkv.", 0), 0u) << during[0];
  sink.close();
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"out.mkv", "out.mkv.part"}));
  EXPECT_EQ(bytes_of(dir / "out.mkv.part"), "someone else's");
  EXPECT_EQ(sink.frames_written(), 1);
}

// A run that fails or is stopped: the existing movie stays as it was, the frames done become a
// playable movie of their own beside it.
TEST(file_sink, abandoned_movie_is_kept_apart_and_the_target_untouched) {
  const auto dir = temp_folder("abandon");
  const cv::Size size{32, 16};
  write_movie(dir / "out.mkv", "ffv1", size, 5);
  const std::string good = bytes_of(dir / "out.mkv");
  {
    FileSink sink(dir / "out.mkv", {.codec = "ffv1", .size = size});
    for (int i = 0; i < 3; ++i) sink.write({test_frame(size, i), i, i / 25.0});
    EXPECT_EQ(sink.abandon(), dir / "out.partial.mkv");
    EXPECT_TRUE(sink.abandon().empty());  // once
  }
  {
    FileSink sink(dir / "out.mkv", {.codec = "ffv1", .size = size});
    sink.write({test_frame(size, 0), 0, 0});
  }  // destroyed without close(): abandoned too, never over the first partial movie
  EXPECT_EQ(bytes_of(dir / "out.mkv"), good);
  EXPECT_EQ(names_in(dir),
            (std::vector<std::string>{"out.mkv", "out.partial-2.mkv", "out.partial.mkv"}));
  FileSource partial(dir / "out.partial.mkv");
  int n = 0;
  while (auto f = partial.read()) {
    EXPECT_EQ(cv::norm(f->image, test_frame(size, n), cv::NORM_INF), 0.0) << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, 3);
}

TEST(file_sink, abandoned_without_frames_keeps_nothing) {
  const auto dir = temp_folder("abandon-empty");
  FileSink sink(dir / "out.mp4", {.size = {16, 16}});
  EXPECT_TRUE(sink.abandon().empty());
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(file_sink, an_input_is_never_the_output) {
  const auto dir = temp_folder("input");
  write_movie(dir / "in.mkv", "ffv1", {16, 16}, 2);
  std::filesystem::create_symlink(dir / "in.mkv", dir / "link.mkv");
  OutputOptions output;
  output.inputs.add(dir / "in.mkv");
  try {
    FileSink sink(dir / "link.mkv", {.codec = "ffv1", .size = {16, 16}, .output = output});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("is the same file as the input"), std::string::npos);
  }
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"in.mkv", "link.mkv"}));
}

TEST(file_sink, a_still_image_container_is_refused_for_a_movie) {
  try {
    resolve_encoder("out.png", "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_STREQ(e.what(),
                 "out.png: a still image format; write an image sequence with a pattern "
                 "such as out_%04d.png");
  }
}

TEST(file_sink, closing_without_frames_leaves_nothing) {
  const auto dir = temp_folder("empty");
  FileSink sink(dir / "out.mp4", {.size = {16, 16}});
  EXPECT_THROW(sink.close(), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(file_sink, frame_of_the_wrong_size_is_refused) {
  const auto dir = temp_folder("wrongsize");
  FileSink sink(dir / "out.mkv", {.codec = "ffv1", .size = {16, 16}});
  EXPECT_THROW(sink.write({test_frame({17, 16}, 0), 0, 0}), Error);
}

// A frame at `pts` on `clock` (lasting `duration` ticks), its picture telling which it is.
Frame timed_frame(cv::Size size, std::int64_t index, std::int64_t pts, Rational clock,
                  std::int64_t duration = 0) {
  Frame f{test_frame(size, index), index, static_cast<double>(pts) * clock.num / clock.den};
  f.pts = pts;
  f.duration = duration;
  f.time_base = clock;
  return f;
}

// A variable-rate source (a phone, dropped frames, a burst) keeps every frame's time exactly
// and its picture: nothing is re-timed to a grid.
TEST(file_sink, kept_timing_writes_each_frame_at_its_own_time) {
  const auto dir = temp_folder("vfr");
  const cv::Size size{32, 24};
  const Rational ms{1, 1000};  // Matroska's clock, so that the times read back exactly
  const std::vector<std::int64_t> times{0, 33, 67, 100, 433, 467, 480, 493, 900, 1500};
  {
    FileSink sink(dir / "a.mkv",
                  {.codec = "ffv1", .size = size, .frame_rate = {30, 1}, .time_base = ms});
    EXPECT_EQ(sink.timing(), FrameTiming::keep);
    for (std::size_t i = 0; i < times.size(); ++i)
      sink.write(timed_frame(size, static_cast<std::int64_t>(i), times[i], ms));
    sink.close();
    EXPECT_EQ(sink.frames_written(), static_cast<std::int64_t>(times.size()));
  }
  FileSource in(dir / "a.mkv");
  std::size_t n = 0;
  while (auto f = in.read()) {
    ASSERT_LT(n, times.size());
    EXPECT_EQ(f->time_base.num, 1);
    EXPECT_EQ(f->time_base.den, 1000);
    EXPECT_EQ(f->pts, times[n]) << "frame " << n;
    EXPECT_DOUBLE_EQ(f->timestamp, times[n] / 1000.0);
    EXPECT_EQ(cv::norm(f->image, test_frame(size, static_cast<std::int64_t>(n)), cv::NORM_INF), 0)
        << "frame " << n;
    ++n;
  }
  EXPECT_EQ(n, times.size());
}

// MP4 keeps the source's clock (here an MP4's own 1/15360) tick for tick, and each frame shows
// the picture of its time.
TEST(file_sink, kept_timing_is_exact_on_the_source_clock_in_mp4) {
  const auto dir = temp_folder("vfr-mp4");
  const cv::Size size{64, 48};
  const Rational clock{1, 15360};
  std::vector<std::int64_t> times;
  for (std::int64_t i = 0, t = 0; i < 24; ++i, t += (i % 5 == 0 ? 1536 : 512)) times.push_back(t);
  {
    FileSink sink(dir / "a.mp4", {.size = size, .frame_rate = {30, 1}, .time_base = clock});
    for (std::size_t i = 0; i < times.size(); ++i)
      sink.write(timed_frame(size, static_cast<std::int64_t>(i), times[i], clock));
    sink.close();
  }
  FileSource in(dir / "a.mp4");
  EXPECT_EQ(in.time_base().den, 15360);
  std::size_t n = 0;
  while (auto f = in.read()) {
    ASSERT_LT(n, times.size());
    EXPECT_EQ(f->pts, times[n]) << "frame " << n;
    EXPECT_GT(cv::PSNR(f->image, test_frame(size, static_cast<std::int64_t>(n))), 28.0);
    ++n;
  }
  EXPECT_EQ(n, times.size());
}

// The slot rule of a constant-rate output, written plainly: slot k shows the last frame whose
// time rounds to slot k or before.
std::vector<std::int64_t> reference_slots(const std::vector<double>& seconds, double rate,
                                          std::int64_t slots) {
  std::vector<std::int64_t> shown;
  for (std::int64_t k = 0; k < slots; ++k) {
    std::int64_t which = -1;
    for (std::size_t i = 0; i < seconds.size(); ++i)
      if (std::llround(seconds[i] * rate) <= k) which = static_cast<std::int64_t>(i);
    shown.push_back(which);
  }
  return shown;
}

TEST(file_sink, constant_timing_repeats_over_gaps_and_drops_within_a_slot) {
  const auto dir = temp_folder("cfr");
  const cv::Size size{32, 24};
  const Rational clock{1, 1000};
  // 10 fps: a gap after 0.2 s, two frames in slot 6 (0.61 s, 0.64 s) and two in slot 7 (0.66 s
  // rounds up, 0.70 s), a late last frame.
  const std::vector<std::int64_t> times{0, 100, 200, 610, 640, 660, 700, 1020};
  std::vector<double> seconds;
  for (auto t : times) seconds.push_back(t / 1000.0);
  FileSink sink(dir / "a.mkv", {.codec = "ffv1",
                                .size = size,
                                .frame_rate = {10, 1},
                                .time_base = clock,
                                .timing = FrameTiming::constant});
  for (std::size_t i = 0; i < times.size(); ++i)
    sink.write(timed_frame(size, static_cast<std::int64_t>(i), times[i], clock, 100));
  sink.close();
  const std::vector<std::int64_t> want = reference_slots(seconds, 10, 11);
  // Slots 0..10: frames 0 1 2 2 2 2 4 6 6 6 7: frame 2 held over the gap, frames 3 and 5 dropped.
  EXPECT_EQ(want, (std::vector<std::int64_t>{0, 1, 2, 2, 2, 2, 4, 6, 6, 6, 7}));
  EXPECT_EQ(sink.frames_written(), 11);
  EXPECT_EQ(sink.frames_repeated(), 5);
  EXPECT_EQ(sink.frames_dropped(), 2);
  FileSource in(dir / "a.mkv");
  std::int64_t k = 0;
  while (auto f = in.read()) {
    ASSERT_LT(k, 11);
    EXPECT_EQ(f->pts, k * 100) << "slot " << k;
    EXPECT_EQ(cv::norm(f->image, test_frame(size, want[static_cast<std::size_t>(k)]), cv::NORM_INF),
              0)
        << "slot " << k << " should show frame " << want[static_cast<std::size_t>(k)];
    ++k;
  }
  EXPECT_EQ(k, 11);
}

TEST(file_sink, timing_follows_what_the_container_can_store) {
  EXPECT_EQ(resolve_timing("x.mp4", "", FrameTiming::automatic), FrameTiming::keep);
  EXPECT_EQ(resolve_timing("x.mkv", "ffv1", FrameTiming::automatic), FrameTiming::keep);
  EXPECT_EQ(resolve_timing("x.avi", "", FrameTiming::automatic), FrameTiming::constant);
  EXPECT_EQ(resolve_timing("x.mpg", "", FrameTiming::automatic), FrameTiming::constant);
  EXPECT_EQ(resolve_timing("x.mp4", "", FrameTiming::constant), FrameTiming::constant);
  try {
    resolve_timing("x.avi", "", FrameTiming::keep);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::unsupported);
    EXPECT_STREQ(e.what(),
                 "x.avi: the avi container cannot keep each frame's time (timing keep); use "
                 ".mkv or .mp4, or timing constant");
  }
}

TEST(file_sink, odd_sides_are_rounded_for_4_2_0_encoders_only) {
  EXPECT_EQ(encodable_size("x.mp4", "", {161, 121}), cv::Size(160, 120));
  EXPECT_EQ(encodable_size("x.mp4", "", {160, 120}), cv::Size(160, 120));
  EXPECT_EQ(encodable_size("x.mp4", "", {1, 1}), cv::Size(2, 2));
  EXPECT_EQ(encodable_size("x.mkv", "ffv1", {161, 121}), cv::Size(161, 121));
  const auto dir = temp_folder("odd");
  try {
    FileSink sink(dir / "out.mp4", {.size = {161, 121}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_EQ(std::string(e.what()),
              (dir / "out.mp4").string() +
                  ": libx264 in yuv420p needs a width that is a multiple of 2 and a height that "
                  "is a multiple of 2 (got 161x121; 160x120 would do)");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace ifsfx::video
