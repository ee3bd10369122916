// SPDX-License-Identifier: Apache-2.0
// What the studio keeps per tab between requests (a movie's decoder, a filter's engine, a
// superIFS's texture sequence): at most `capacity` slots, the one used longest ago forgotten to
// make room. Not locked: each owner holds its own mutex around it.
//
//   LruSlots<Cursor> cursors(8);
//   if (auto c = cursors.take(tab)) ...;            // out while in use
//   for (auto& gone : cursors.put(tab, c)) ...;     // back, the oldest beyond 8 handed back
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ifsfx::app {

template <class Value>
class LruSlots {
 public:
  explicit LruSlots(std::size_t capacity) : capacity_(capacity) {}

  // The value of `slot`, now the most recently used; null when there is none.
  std::shared_ptr<Value> find(const std::string& slot) {
    const auto it = slots_.find(slot);
    if (it == slots_.end()) return nullptr;
    it->second.used = ++clock_;
    return it->second.value;
  }

  // The value of `slot`, removed (the caller puts it back when done); null when there is none.
  std::shared_ptr<Value> take(const std::string& slot) {
    const auto it = slots_.find(slot);
    if (it == slots_.end()) return nullptr;
    std::shared_ptr<Value> value = std::move(it->second.value);
    slots_.erase(it);
    return value;
  }

  // Sets `slot` to `value`, the most recently used, and returns the values forgotten to keep
  // `capacity` slots (oldest first), for the caller to stop.
  std::vector<std::shared_ptr<Value>> put(const std::string& slot, std::shared_ptr<Value> value) {
    slots_[slot] = {std::move(value), ++clock_};
    std::vector<std::shared_ptr<Value>> forgotten;
    while (slots_.size() > capacity_) {
      auto oldest = slots_.begin();
      for (auto it = slots_.begin(); it != slots_.end(); ++it)
        if (it->second.used < oldest->second.used) oldest = it;
      forgotten.push_back(std::move(oldest->second.value));
      slots_.erase(oldest);
    }
    return forgotten;
  }

  template <class Visit>
  void for_each(Visit&& visit) const {
    for (const auto& [slot, item] : slots_) visit(*item.value);
  }
  std::size_t size() const { return slots_.size(); }

 private:
  struct Item {
    std::shared_ptr<Value> value;
    std::uint64_t used = 0;
  };
  std::size_t capacity_;
  std::map<std::string, Item> slots_;
  std::uint64_t clock_ = 0;
};

// The slot's entry made for settings `key` (Entry has `std::string key` and `std::atomic<bool>
// stop`): the one kept when its key is the same, otherwise a new one, and the entry it replaces
// (and any forgotten to make room) asked to stop, so that work still running for old settings
// ends (409).
template <class Entry>
std::shared_ptr<Entry> entry_for(LruSlots<Entry>& slots, const std::string& slot,
                                 const std::string& key) {
  std::shared_ptr<Entry> entry = slots.find(slot);
  if (entry && entry->key == key) return entry;
  if (entry) entry->stop = true;
  entry = std::make_shared<Entry>();
  entry->key = key;
  for (const auto& gone : slots.put(slot, entry)) gone->stop = true;
  return entry;
}

}  // namespace ifsfx::app
