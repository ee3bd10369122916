// SPDX-License-Identifier: Apache-2.0
// The maps of an animated filter (--animate drift, --animate superifs), built ahead of need on a
// worker thread so that frames keep flowing while the next map is computed.
//
// Determinism: keyframe k is a pure function of k, and frame i shows keyframe ⌊i/K⌋ cross-faded
// into keyframe ⌊i/K⌋ + 1 by (i mod K)/K. Which map a frame gets depends only on its index, never
// on how fast the worker was: when a keyframe is late the filter waits for it (counted in
// stalls()) rather than show an older map. Keyframe k + 2 is started as soon as frame k·K is
// needed, so it has K frames' time to be ready.
#pragma once

#include <cstdint>
#include <functional>
#include <future>
#include <map>
#include <memory>

#include "engine/fractal_filter.h"
#include "ifs/timeline.h"

namespace ifsfx::engine {

class MapSchedule {
 public:
  using Builder = std::function<PreparedStealMap(std::int64_t keyframe)>;

  // `interval` = K, frames between keyframes (≥ 1). The builder runs on worker threads, at most
  // `lookahead` keyframes ahead of the one shown; it must be safe to call concurrently.
  MapSchedule(Builder builder, int interval, int lookahead = 2);
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

  // Frames that had to wait for their map, after the first (which always waits for the start).
  std::int64_t stalls() const { return stalls_; }

 private:
  using Table = std::shared_ptr<const PreparedStealMap>;
  std::shared_future<Table>& keyframe(std::int64_t k);

  Builder builder_;
  int interval_;
  int lookahead_;
  std::map<std::int64_t, std::shared_future<Table>> keyframes_;
  std::int64_t stalls_ = 0;
  bool started_ = false;
};

}  // namespace ifsfx::engine
