#include "video/file_sink.h"

#include <fstream>

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

TEST(file_sink, unfinished_file_never_takes_the_output_name) {
  const auto dir = temp_folder("partial");
  FileSink sink(dir / "out.mkv", {.codec = "ffv1", .size = {16, 16}});
  sink.write({test_frame({16, 16}, 0), 0, 0});
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mkv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out.mkv.part"));
  sink.close();
  EXPECT_TRUE(std::filesystem::exists(dir / "out.mkv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.mkv.part"));
  EXPECT_EQ(sink.frames_written(), 1);
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

}  // namespace
}  // namespace ifsfx::video
