// SPDX-License-Identifier: Apache-2.0
// Live drift: the first frame shows the map of time 0, later maps arrive from the worker without
// the caller ever waiting for them, and a new map fades in rather than cuts.
#include "engine/camera_drift.h"

#include <thread>

#include <gtest/gtest.h>

#include "ifs/preset.h"
#include "ifs/view.h"

namespace ifsfx::engine {
namespace {

using namespace std::chrono_literals;

struct Fixture {
  Ifs F = load_ifs("sierpinski-triangle").ifs;
  Ifs G = default_colouring(F.size());
  cv::Size size{48, 32};
  cv::Mat frame;
  LiveDriftOptions options;
  Fixture() {
    frame.create(size, CV_8UC3);
    cv::randu(frame, 0, 256);
    options.drift = {.amount = 0.2, .speed = 1, .seed = 3};
    options.map.sampling.quality = 8;
    options.map.sampling.threads = 1;
    options.map.exact = false;  // the chaos game's map
    options.fade_frames = 4;
  }
};

TEST(camera_drift, the_first_frame_shows_the_map_of_time_zero) {
  const Fixture x;
  LiveDrift live(x.F, x.G, x.size, x.options);
  StealMapOptions map = x.options.map;
  map.sampling.view =
      fit_view(attractor_bounds(x.F, map.sampling.seed), x.size, map.sampling.margin);
  const PreparedStealMap table =
      prepare_filter(compute_steal_map(drift(x.F, 0, x.options.drift), x.G, x.size, map), x.size);
  const cv::Mat got = live.filter(x.frame, 0.5);
  EXPECT_EQ(cv::norm(got, filter_frame(x.frame, table), cv::NORM_INF), 0);
}

TEST(camera_drift, new_maps_arrive_from_the_worker_without_waiting) {
  const Fixture x;
  LiveDrift live(x.F, x.G, x.size, x.options);
  const cv::Mat first = live.filter(x.frame, 0.0);
  // Every later frame asks for the one time t = 0.5. The first map built in the background is of
  // t = 0 again, the second and any after it are of t = 0.5; filtering until it has arrived and
  // its fade is over must give the frame through that map, whatever the timing.
  constexpr double t = 0.5;
  for (int i = 1; i < 2000 && live.maps_built() < 3; ++i) {
    live.filter(x.frame, t);
    std::this_thread::sleep_for(5ms);
  }
  ASSERT_GE(live.maps_built(), 3);
  cv::Mat now;
  for (int i = 0; i < x.options.fade_frames; ++i) now = live.filter(x.frame, t);

  StealMapOptions map = x.options.map;
  map.sampling.view =
      fit_view(attractor_bounds(x.F, map.sampling.seed), x.size, map.sampling.margin);
  const cv::Mat drifted = filter_frame(
      x.frame,
      prepare_filter(compute_steal_map(drift(x.F, t, x.options.drift), x.G, x.size, map), x.size));
  ASSERT_GT(cv::norm(drifted, first, cv::NORM_L1), 0) << "the drift at t = 0.5 moved no pixel";
  EXPECT_EQ(cv::norm(now, drifted, cv::NORM_INF), 0) << "the drifted map never showed";
}

}  // namespace
}  // namespace ifsfx::engine
