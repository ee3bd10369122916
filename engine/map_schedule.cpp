// SPDX-License-Identifier: Apache-2.0
#include "engine/map_schedule.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <iterator>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include "ifs/error.h"

namespace ifsfx::engine {
namespace {

// How much lower a live build runs than the thread that asked for it: nice 10 gets about a tenth
// of a core that a nice-0 thread wants (the kernel's weights 110 and 1024).
constexpr int kLiveBuildNice = 10;

// Lowers the calling thread (a build's own, started for it; the threads it starts inherit it).
// Nothing depends on it but when the build is ready: a failure leaves the thread as it was.
void lower_priority() {
  const auto tid = static_cast<id_t>(gettid());
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, tid);
  if (errno == 0) setpriority(PRIO_PROCESS, tid, std::min(nice + kLiveBuildNice, 19));
}

template <typename Future>
bool finished(const Future& f) {
  return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

}  // namespace

MapSchedule::MapSchedule(Builder builder, int interval, ScheduleOptions options)
    : builder_(std::move(builder)), interval_(interval), options_(options) {
  options_.lookahead = std::max(1, options.lookahead);
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
    // Live, the builds before the first picture keep the caller's priority: no picture waits on
    // the thread then, the frames pass through until it is ready.
    auto future = std::async(std::launch::async, [this, k, lower = options_.live && started_] {
      if (lower) lower_priority();
      return std::make_shared<const PreparedStealMap>(builder_(k));
    });
    it = keyframes_.emplace(k, future.share()).first;
  }
  return it->second;
}

bool MapSchedule::ready(std::int64_t k) const {
  const auto it = keyframes_.find(k);
  return it != keyframes_.end() && finished(it->second);
}

MapSchedule::Blend MapSchedule::at(std::int64_t frame) {
  return at(position_of_frame(frame, interval_));
}

MapSchedule::Blend MapSchedule::at(StepPosition position) {
  return options_.live ? live(position) : keyed(position);
}

MapSchedule::Blend MapSchedule::keyed(StepPosition position) {
  const std::int64_t k = position.step;
  // Forget keyframes behind the one shown and beyond the lookahead (a caller going backwards, an
  // editor scrubbing); start the ones ahead.
  while (!keyframes_.empty() && keyframes_.begin()->first < k) {
    keyframes_.begin()->second.wait();
    keyframes_.erase(keyframes_.begin());
  }
  while (!keyframes_.empty() && std::prev(keyframes_.end())->first > k + options_.lookahead) {
    std::prev(keyframes_.end())->second.wait();
    keyframes_.erase(std::prev(keyframes_.end()));
  }
  for (std::int64_t j = k; j <= k + options_.lookahead; ++j) keyframe(j);
  auto& from = keyframe(k);
  auto& to = keyframe(k + 1);
  if (started_ && (!finished(from) || !finished(to))) ++stalls_;
  started_ = true;
  Blend blend;
  blend.from = from.get();
  blend.to = to.get();
  blend.t = position.phase;
  return blend;
}

MapSchedule::Keyframes::iterator MapSchedule::newest_ready(std::int64_t k) {
  for (auto it = keyframes_.upper_bound(k); it != keyframes_.begin();)
    if (finished((--it)->second)) return it;
  return keyframes_.end();
}

void MapSchedule::forget_live(std::int64_t k) {
  // The newest ready keyframe at or before k is kept: it is what a late position shows.
  const auto held = newest_ready(k);
  for (auto it = keyframes_.begin(); it != keyframes_.end();) {
    const bool needed = (it->first >= k && it->first <= k + options_.lookahead) || it == held;
    // A build still running is let finish (see the header) and forgotten once it has.
    it = !needed && finished(it->second) ? keyframes_.erase(it) : std::next(it);
  }
}

void MapSchedule::start_next(std::int64_t k) {
  for (const auto& [j, f] : keyframes_)
    if (!finished(f)) return;  // one build at a time
  for (std::int64_t j = k; j <= k + options_.lookahead; ++j)
    if (!keyframes_.contains(j)) {
      keyframe(j);
      return;
    }
}

MapSchedule::Blend MapSchedule::live(StepPosition position) {
  const std::int64_t k = position.step;
  forget_live(k);
  start_next(k);
  if (!started_) {  // the first picture waits for its keyframe, the next build starts after it
    keyframes_.at(k).wait();
    start_next(k);
  }
  Blend blend;
  if (ready(k) && ready(k + 1)) {
    blend = {keyframes_.at(k).get(), keyframes_.at(k + 1).get(), position.phase};
  } else {
    if (started_) ++stalls_;
    const auto held = newest_ready(k);
    blend = held == keyframes_.end() ? last_ : Blend{held->second.get(), held->second.get(), 0};
  }
  started_ = true;
  last_ = blend;
  return blend;
}

}  // namespace ifsfx::engine
