// SPDX-License-Identifier: Apache-2.0
#include "engine/map_schedule.h"

#include <atomic>
#include <mutex>
#include <set>

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

TEST(map_schedule, interval_must_be_positive) {
  EXPECT_THROW(MapSchedule(table_for, 0), Error);
}

}  // namespace
}  // namespace ifsfx::engine
