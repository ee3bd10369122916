// SPDX-License-Identifier: Apache-2.0
// The maps of an animated filter (--animate drift, --animate superifs), built ahead of need on
// worker threads so that frames keep flowing while the next map is computed. Two rules, one per
// kind of source:
//
// Frame-keyed (files: `ifsfx filter`, a farm shard, frei0r; the default). Keyframe k is a pure
// function of k, and frame i shows keyframe ⌊i/K⌋ cross-faded into keyframe ⌊i/K⌋ + 1 by
// (i mod K)/K. Which map a frame gets depends only on its index, never on how fast the workers
// were: when a keyframe is late the filter waits for it (counted in stalls()) rather than show an
// older map. Keyframes k … k + lookahead are started as soon as frame k·K is needed, each on its
// own thread, so keyframe k + 2 has K frames' time to be ready.
//
// Live (a camera through the OBS filter: options.live). A frame never waits for a keyframe but
// the first picture's (it waits for keyframe k alone). The position (k, φ) is shown exactly when
// keyframes k and k + 1 are ready; otherwise the newest ready keyframe j ≤ k is shown alone
// (position (j, 0), the picture of frame j·K); with none ready (the source went back in time), the
// last picture's maps. Each is a pair of maps the frame-keyed rule gives some frame, and but for a
// source gone back never a later one than asked. Keyframes are built one at a time, in order, on a
// thread at a lower priority once a picture has been shown (nice 10, so that the frames' own work
// comes first; the engine's builders use one thread for a live source), the lowest
// keyframe of k … k + lookahead not yet built next: a keyframe the position has passed before its
// build started is never built. A build already running when the position passes it is let finish
// (it becomes the newest ready keyframe ≤ k and is shown, so the animation moves on at the builds'
// pace even when every build is late; cancelling it could show nothing new for good).
#pragma once

#include <cstdint>
#include <functional>
#include <future>
#include <map>
#include <memory>

#include "engine/fractal_filter.h"
#include "ifs/timeline.h"

namespace ifsfx::engine {

struct ScheduleOptions {
  int lookahead = 2;  // keyframes built ahead of the one shown (≥ 1)
  bool live = false;  // the live rule (above) instead of the frame-keyed one
};

class MapSchedule {
 public:
  using Builder = std::function<PreparedStealMap(std::int64_t keyframe)>;

  // `interval` = K, frames between keyframes (≥ 1). The builder runs on worker threads; it must be
  // safe to call concurrently.
  MapSchedule(Builder builder, int interval, ScheduleOptions options = {});
  ~MapSchedule();
  MapSchedule(const MapSchedule&) = delete;
  MapSchedule& operator=(const MapSchedule&) = delete;

  struct Blend {
    std::shared_ptr<const PreparedStealMap> from, to;
    double t = 0;  // weight of `to`
  };
  // The maps of source frame `frame`. Rethrows a builder's error.
  Blend at(std::int64_t frame);
  // The maps at a position between keyframes (position.step, its phase towards the next), for
  // callers that know a time rather than a frame number.
  Blend at(StepPosition position);

  // Frames whose maps were late, after the first (which always waits for the start): frame-keyed,
  // the frames that waited; live, the frames shown at an earlier position than asked.
  std::int64_t stalls() const { return stalls_; }

 private:
  using Table = std::shared_ptr<const PreparedStealMap>;
  using Keyframes = std::map<std::int64_t, std::shared_future<Table>>;
  std::shared_future<Table>& keyframe(std::int64_t k);
  // The newest keyframe at or before k whose build has finished; end() for none.
  Keyframes::iterator newest_ready(std::int64_t k);
  bool ready(std::int64_t k) const;
  Blend keyed(StepPosition position);
  Blend live(StepPosition position);
  // Live: forgets the keyframes no longer needed, finished ones only.
  void forget_live(std::int64_t k);
  // Live: starts the lowest keyframe of k … k + lookahead not yet built when none is building.
  void start_next(std::int64_t k);

  Builder builder_;
  int interval_;
  ScheduleOptions options_;
  Keyframes keyframes_;
  Blend last_;  // live: the maps of the last picture
  std::int64_t stalls_ = 0;
  bool started_ = false;
};

}  // namespace ifsfx::engine
