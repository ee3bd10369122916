// SPDX-License-Identifier: Apache-2.0
// The editor's renders in flight, one per tab (docs/studio.md): a newer render of a tab stops
// that tab's older one, which then answers 409, so that a drag never queues stale pictures; the
// other tabs' renders go on.
//
//   const auto flag = renders.start(tab);    // the tab's older render is asked to stop
//   ... render_picture(request, CancelToken(flag.get())) ...
//   renders.finish(tab, flag);
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace ifsfx::app {

class TabRenders {
 public:
  using Flag = std::shared_ptr<std::atomic<bool>>;

  // A stop flag for a new render of tab `client`; the tab's render in flight is asked to stop.
  Flag start(const std::string& client) {
    auto flag = std::make_shared<std::atomic<bool>>(false);
    std::lock_guard lock(mutex_);
    Flag& current = in_flight_[client];
    if (current) current->store(true);
    current = flag;
    return flag;
  }
  // Forgets `flag` unless a newer render of the tab took its place.
  void finish(const std::string& client, const Flag& flag) {
    std::lock_guard lock(mutex_);
    const auto it = in_flight_.find(client);
    if (it != in_flight_.end() && it->second == flag) in_flight_.erase(it);
  }
  // Asks every render in flight to stop (the server stops).
  void cancel_all() {
    std::lock_guard lock(mutex_);
    for (auto& [client, flag] : in_flight_) flag->store(true);
  }
  // How many tabs have a render in flight.
  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return in_flight_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Flag> in_flight_;  // stop flags by tab
};

}  // namespace ifsfx::app
