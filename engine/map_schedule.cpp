// SPDX-License-Identifier: Apache-2.0
#include "engine/map_schedule.h"

#include <chrono>
#include <iterator>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::engine {

MapSchedule::MapSchedule(Builder builder, int interval, int lookahead)
    : builder_(std::move(builder)), interval_(interval), lookahead_(std::max(1, lookahead)) {
  if (interval < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("keyframe interval: must be 1 or more frames (got {})", interval));
}

MapSchedule::~MapSchedule() {
  // Futures of std::async block in their destructor until the builder returns: wait here, once.
  for (auto& [k, f] : keyframes_)
    if (f.valid()) f.wait();
}

std::shared_future<MapSchedule::Table>& MapSchedule::keyframe(std::int64_t k) {
  auto it = keyframes_.find(k);
  if (it == keyframes_.end()) {
    auto future = std::async(std::launch::async, [this, k] {
      return std::make_shared<const PreparedStealMap>(builder_(k));
    });
    it = keyframes_.emplace(k, future.share()).first;
  }
  return it->second;
}

MapSchedule::Blend MapSchedule::at(std::int64_t frame) {
  return at(position_of_frame(frame, interval_));
}

MapSchedule::Blend MapSchedule::at(StepPosition position) {
  const std::int64_t k = position.step;
  // Forget keyframes behind the one shown and beyond the lookahead (a caller going backwards, an
  // editor scrubbing); start the ones ahead.
  while (!keyframes_.empty() && keyframes_.begin()->first < k) {
    keyframes_.begin()->second.wait();
    keyframes_.erase(keyframes_.begin());
  }
  while (!keyframes_.empty() && std::prev(keyframes_.end())->first > k + lookahead_) {
    std::prev(keyframes_.end())->second.wait();
    keyframes_.erase(std::prev(keyframes_.end()));
  }
  for (std::int64_t j = k; j <= k + lookahead_; ++j) keyframe(j);
  auto& from = keyframe(k);
  auto& to = keyframe(k + 1);
  using namespace std::chrono_literals;
  if (started_ && (from.wait_for(0s) != std::future_status::ready ||
                   to.wait_for(0s) != std::future_status::ready))
    ++stalls_;
  started_ = true;
  Blend blend;
  blend.from = from.get();
  blend.to = to.get();
  blend.t = position.phase;
  return blend;
}

}  // namespace ifsfx::engine
