// SPDX-License-Identifier: Apache-2.0
#include "engine/map_schedule.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "tests/video/test_frames.h"

namespace ifsfx::engine {
namespace {

// A table whose every pixel takes the source at column k: identifies keyframe k in a 1-row map.
PreparedStealMap table_for(std::int64_t k) {
  StealMap map = video::testing::identity_map({1, 1});
  map.source_uv.at<cv::Vec2f>(0, 0) = {(static_cast<float>(k) + 0.5f) / 64, 0.5f};
  return prepare_filter(map, {64, 2}, Interpolation::nearest);
}

std::int64_t keyframe_of(const PreparedStealMap& t) {
  return t.xy.at<cv::Vec2s>(0, 0)[0];
}

TEST(map_schedule, frame_shows_its_keyframe_faded_into_the_next) {
  std::mutex mutex;
  std::set<std::int64_t> built;
  MapSchedule schedule(
      [&](std::int64_t k) {
        std::lock_guard lock(mutex);
        built.insert(k);
        return table_for(k);
      },
      4);
  for (std::int64_t i = 0; i < 20; ++i) {
    const MapSchedule::Blend b = schedule.at(i);
    EXPECT_EQ(keyframe_of(*b.from), i / 4) << "frame " << i;
    EXPECT_EQ(keyframe_of(*b.to), i / 4 + 1) << "frame " << i;
    EXPECT_DOUBLE_EQ(b.t, (i % 4) / 4.0);
  }
  // Keyframes 0..5 were shown; 6 may still be building ahead on its worker.
  std::lock_guard lock(mutex);
  for (std::int64_t k = 0; k <= 5; ++k) EXPECT_EQ(built.count(k), 1u) << "keyframe " << k;
}

TEST(map_schedule, starting_mid_way_gives_the_same_maps) {
  MapSchedule from_start(table_for, 3), from_middle(table_for, 3);
  for (std::int64_t i = 0; i < 10; ++i) from_start.at(i);
  for (std::int64_t i = 10; i < 16; ++i) {
    const auto a = from_start.at(i), b = from_middle.at(i);
    EXPECT_EQ(keyframe_of(*a.from), keyframe_of(*b.from));
    EXPECT_EQ(keyframe_of(*a.to), keyframe_of(*b.to));
    EXPECT_EQ(a.t, b.t);
  }
}

TEST(map_schedule, builder_error_reaches_the_caller) {
  MapSchedule schedule(
      [](std::int64_t k) -> PreparedStealMap {
        if (k == 2) throw Error(ErrorKind::invalid_ifs, "drift: map went wrong");
        return table_for(k);
      },
      5);
  EXPECT_NO_THROW(schedule.at(0));
  EXPECT_THROW(schedule.at(5), Error);
}

// Keyframe builds the test lets finish: build(k) returns only once k is released (or after 10 s,
// so that a schedule that waits for an unreleased keyframe fails its checks instead of hanging).
class Gate {
 public:
  PreparedStealMap build(std::int64_t k) {
    std::unique_lock lock(mutex_);
    started_.insert(k);
    changed_.notify_all();
    changed_.wait_for(lock, std::chrono::seconds(10), [&] { return released_.count(k) > 0; });
    return table_for(k);
  }
  void release(std::initializer_list<std::int64_t> keyframes) {
    std::lock_guard lock(mutex_);
    released_.insert(keyframes);
    changed_.notify_all();
  }
  bool started(std::int64_t k) {
    std::lock_guard lock(mutex_);
    return started_.count(k) > 0;
  }
  void wait_started(std::int64_t k) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return started_.count(k) > 0; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::set<std::int64_t> started_, released_;
};

// The maps of `frame` once `done` holds for them: a released build becomes ready a moment after
// it returns.
template <typename Done>
MapSchedule::Blend once(MapSchedule& schedule, std::int64_t frame, Done done) {
  MapSchedule::Blend b = schedule.at(frame);
  for (int i = 0; i < 1000 && !done(b); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    b = schedule.at(frame);
  }
  return b;
}

TEST(map_schedule, live_frames_never_wait_for_a_late_keyframe_nor_build_one_skipped) {
  Gate gate;
  gate.release({0, 1});
  MapSchedule schedule([&](std::int64_t k) { return gate.build(k); }, 4, {.live = true});
  // The first picture waits for its keyframe; frame 3 then fades 0 into 1 as a file's does.
  EXPECT_EQ(keyframe_of(*schedule.at(0).from), 0);
  MapSchedule::Blend b = once(schedule, 3, [](const auto& m) { return keyframe_of(*m.to) == 1; });
  EXPECT_EQ(keyframe_of(*b.from), 0);
  EXPECT_EQ(keyframe_of(*b.to), 1);
  EXPECT_DOUBLE_EQ(b.t, 0.75);
  // Keyframe 2 is building and held back: frames 4 and 6 show keyframe 1 alone (frame 4's
  // picture) at once instead of waiting for it.
  gate.wait_started(2);
  const std::int64_t stalls = schedule.stalls();
  for (const std::int64_t frame : {4, 6}) {
    b = schedule.at(frame);
    EXPECT_EQ(keyframe_of(*b.from), 1) << frame;
    EXPECT_EQ(keyframe_of(*b.to), 1) << frame;
    EXPECT_EQ(b.t, 0) << frame;
  }
  EXPECT_EQ(schedule.stalls(), stalls + 2) << "the frames shown at an earlier position";
  // The source jumps to frame 20 (keyframe 5) while 2 builds: one build at a time, so 3 and 4
  // are not started; once 2 is ready it is shown (the newest ready at or before 5) and 5 starts.
  EXPECT_EQ(keyframe_of(*schedule.at(20).from), 1);
  gate.release({2});
  b = once(schedule, 20, [](const auto& m) { return keyframe_of(*m.from) == 2; });
  EXPECT_EQ(keyframe_of(*b.from), 2);
  gate.wait_started(5);
  gate.release({5, 6, 7});
  b = once(schedule, 20, [](const auto& m) { return keyframe_of(*m.to) == 6; });
  EXPECT_EQ(keyframe_of(*b.from), 5);
  EXPECT_EQ(keyframe_of(*b.to), 6);
  EXPECT_FALSE(gate.started(3));
  EXPECT_FALSE(gate.started(4));
  gate.release({3, 4, 8});
}

TEST(map_schedule, interval_must_be_positive) {
  EXPECT_THROW(MapSchedule(table_for, 0), Error);
}

}  // namespace
}  // namespace ifsfx::engine
