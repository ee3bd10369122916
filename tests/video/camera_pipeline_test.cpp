// SPDX-License-Identifier: Apache-2.0
// The live loop of `ifsfx cam` on the host, fed by the synthetic paced camera: frame counts,
// newest-frame dropping, the stop flag, and the fault path that must keep the recording.
#include "video/camera_pipeline.h"

#include <thread>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "video/camera_synthetic.h"

namespace ifsfx::video {
namespace {

using namespace std::chrono_literals;

// A sink that keeps what it was given.
class MemorySink final : public FrameSink {
 public:
  void write(const Frame& frame) override {
    if (closed) throw Error(ErrorKind::io, "memory: write after close");
    indices.push_back(frame.index);
    images.push_back(frame.image.clone());
  }
  void close() override {
    ++closes;
    closed = true;
  }
  std::string name() const override { return "memory"; }

  std::vector<std::int64_t> indices;
  std::vector<cv::Mat> images;
  int closes = 0;
  bool closed = false;
};

SyntheticCameraOptions small(double fps) {
  SyntheticCameraOptions o;
  o.size = {32, 24};
  o.fps = fps;
  o.patterns = 8;
  return o;
}

TEST(camera_pipeline, max_frames_stops_after_exactly_n_frames_and_closes_the_sinks) {
  SyntheticCamera camera(small(1000));
  MemorySink sink;
  const CameraStats stats = run_camera(camera, {}, {&sink}, {.max_frames = 7});
  EXPECT_EQ(stats.frames, 7);
  EXPECT_EQ(sink.indices.size(), 7u);
  EXPECT_EQ(sink.closes, 1);
  // Without a filter the frames pass unchanged.
  for (std::size_t i = 0; i < sink.images.size(); ++i) {
    EXPECT_EQ(cv::norm(sink.images[i], camera.pattern(sink.indices[i]), cv::NORM_INF), 0);
  }
}

TEST(camera_pipeline, the_filter_output_is_what_the_sinks_get) {
  SyntheticCamera camera(small(1000));
  MemorySink sink;
  run_camera(camera, [](const Frame& f) { return cv::Mat(255 - f.image); }, {&sink},
             {.max_frames = 3});
  ASSERT_EQ(sink.images.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(
        cv::norm(sink.images[i], cv::Mat(255 - camera.pattern(sink.indices[i])), cv::NORM_INF), 0);
  }
}

TEST(camera_pipeline, a_slow_filter_gets_the_newest_frame_and_older_ones_are_dropped) {
  // 200 fps source, a filter that takes 25 ms: about 5 frames are captured per frame filtered;
  // the loop must skip to the newest each time rather than work through a backlog.
  SyntheticCamera camera(small(200));
  MemorySink sink;
  const CameraStats stats = run_camera(camera,
                                       [](const Frame& f) {
                                         std::this_thread::sleep_for(25ms);
                                         return f.image;
                                       },
                                       {&sink}, {.max_frames = 6});
  ASSERT_EQ(sink.indices.size(), 6u);
  for (std::size_t i = 1; i < sink.indices.size(); ++i) {
    EXPECT_GE(sink.indices[i] - sink.indices[i - 1], 2) << "frame " << i << " came from a queue";
  }
  EXPECT_EQ(stats.dropped, sink.indices.back() + 1 - 6);  // every frame not filtered
  EXPECT_GT(stats.drop_fraction(), 0);
}

TEST(camera_pipeline, the_stop_flag_ends_the_loop_between_frames) {
  SyntheticCamera camera(small(500));
  MemorySink sink;
  std::atomic<bool> stop{false};
  int seen = 0;
  const CameraStats stats =
      run_camera(camera, {}, {&sink}, {.stop = &stop}, [&](const Frame&, const CameraStats&) {
        if (++seen == 4) stop = true;
        return true;
      });
  EXPECT_EQ(stats.frames, 4);
  EXPECT_EQ(sink.closes, 1);
}

TEST(camera_pipeline, the_observer_can_quit) {
  SyntheticCamera camera(small(500));
  MemorySink sink;
  const CameraStats stats = run_camera(
      camera, {}, {&sink}, {}, [](const Frame&, const CameraStats& s) { return s.frames < 3; });
  EXPECT_EQ(stats.frames, 3);
}

TEST(camera_pipeline, a_source_fault_closes_the_sinks_then_reports_the_fault) {
  SyntheticCameraOptions o = small(1000);
  o.fail_after = 5;
  SyntheticCamera camera(o);
  MemorySink sink;
  try {
    run_camera(camera, {}, {&sink});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::device);
    EXPECT_STREQ(e.what(), "synthetic: device vanished (simulated)");
  }
  EXPECT_EQ(sink.indices.size(), 5u);
  EXPECT_EQ(sink.closes, 1);
}

TEST(camera_pipeline, a_sink_fault_closes_every_sink) {
  class FailingSink final : public FrameSink {
   public:
    void write(const Frame&) override { throw Error(ErrorKind::device, "out: gone"); }
    void close() override { ++closes; }
    std::string name() const override { return "out"; }
    int closes = 0;
  };
  SyntheticCamera camera(small(1000));
  MemorySink recording;
  FailingSink output;
  EXPECT_THROW(run_camera(camera, {}, {&recording, &output}), Error);
  EXPECT_EQ(recording.closes, 1);
  EXPECT_EQ(output.closes, 1);
}

TEST(camera_pipeline, the_end_of_the_source_ends_the_loop) {
  SyntheticCameraOptions o = small(1000);
  o.frame_count = 5;
  SyntheticCamera camera(o);
  MemorySink sink;
  const CameraStats stats = run_camera(camera, {}, {&sink});
  EXPECT_LE(stats.frames, 5);
  EXPECT_EQ(stats.frames + stats.dropped, 5);
  EXPECT_EQ(sink.closes, 1);
}

TEST(synthetic_camera, read_returns_the_newest_frame_captured) {
  SyntheticCamera camera(small(100));
  std::this_thread::sleep_for(100ms);  // frames 0..~10 captured meanwhile
  const Frame f = *camera.read();
  EXPECT_GE(f.index, 9);
  EXPECT_EQ(camera.dropped(), f.index);
  EXPECT_DOUBLE_EQ(f.timestamp, f.index / 100.0);
  // The next read waits for the next frame instead of repeating this one.
  EXPECT_GT(camera.read()->index, f.index);
}

TEST(synthetic_camera, consecutive_patterns_differ) {
  SyntheticCamera camera(small(30));
  EXPECT_GT(cv::norm(camera.pattern(0), camera.pattern(1), cv::NORM_L1), 0);
  EXPECT_EQ(cv::norm(camera.pattern(0), camera.pattern(8), cv::NORM_INF), 0);  // 8 patterns
}

}  // namespace
}  // namespace ifsfx::video
