// SPDX-License-Identifier: Apache-2.0
// What the studio keeps per tab (studio/lru.h): at most N slots, the one used longest ago
// forgotten; an entry kept while its settings stay, replaced and stopped when they change.
#include "studio/lru.h"

#include <atomic>
#include <string>

#include <gtest/gtest.h>

namespace ifsfx::app {
namespace {

TEST(lru_slots, forgets_the_slot_used_longest_ago) {
  LruSlots<int> slots(2);
  EXPECT_TRUE(slots.put("a", std::make_shared<int>(1)).empty());
  EXPECT_TRUE(slots.put("b", std::make_shared<int>(2)).empty());
  EXPECT_EQ(*slots.find("a"), 1);  // a is now newer than b
  const auto gone = slots.put("c", std::make_shared<int>(3));
  ASSERT_EQ(gone.size(), 1u);
  EXPECT_EQ(*gone[0], 2);
  EXPECT_EQ(slots.find("b"), nullptr);
  EXPECT_EQ(slots.size(), 2u);
}

TEST(lru_slots, take_removes_until_put_back) {
  LruSlots<int> slots(2);
  slots.put("a", std::make_shared<int>(1));
  const auto a = slots.take("a");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(slots.take("a"), nullptr);
  EXPECT_EQ(slots.size(), 0u);
  slots.put("a", a);
  EXPECT_EQ(slots.find("a"), a);
}

struct Entry {
  std::string key;
  std::atomic<bool> stop{false};
};

TEST(entry_for, keeps_the_entry_of_the_same_settings_and_stops_the_replaced_one) {
  LruSlots<Entry> slots(1);
  const auto first = entry_for(slots, "tab", "look 1");
  EXPECT_EQ(entry_for(slots, "tab", "look 1"), first);
  EXPECT_FALSE(first->stop);
  const auto second = entry_for(slots, "tab", "look 2");
  EXPECT_NE(second, first);
  EXPECT_TRUE(first->stop);
  const auto other = entry_for(slots, "other tab", "look 2");  // capacity 1: "tab" forgotten
  EXPECT_TRUE(second->stop);
  EXPECT_FALSE(other->stop);
}

}  // namespace
}  // namespace ifsfx::app
