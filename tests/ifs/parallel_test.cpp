// SPDX-License-Identifier: Apache-2.0
// parallel_rows: fixed bands of rows, the same split for any thread count, and a stop request
// polled before each band; the per-worker rasters' allocator.
#include "ifs/parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/large_buffer.h"

namespace ifsfx {
namespace {

using Bands = std::set<std::pair<int, int>>;

Bands bands_of(int rows, int band, int threads) {
  Bands bands;
  std::mutex mutex;
  parallel_rows(rows, band, threads, [&](cv::Range r) {
    std::lock_guard lock(mutex);
    bands.insert({r.start, r.end});
  });
  return bands;
}

TEST(parallel_rows, splits_rows_into_fixed_bands_for_any_thread_count) {
  const Bands expected{{0, 16}, {16, 32}, {32, 37}};
  for (const int threads : {1, 2, 7}) EXPECT_EQ(bands_of(37, 16, threads), expected) << threads;
  EXPECT_EQ(bands_of(32, 16, 3), (Bands{{0, 16}, {16, 32}}));
  EXPECT_TRUE(bands_of(0, 8, 2).empty());
}

TEST(parallel_rows, covers_every_row_of_every_plane_once) {
  std::vector<std::atomic<int>> seen(3 * 21);
  parallel_rows(3, 21, 8, 4, CancelToken(), "test", [&](std::size_t plane, cv::Range r) {
    for (int row = r.start; row < r.end; ++row) ++seen[plane * 21 + static_cast<std::size_t>(row)];
  });
  for (const auto& count : seen) EXPECT_EQ(count, 1);
}

TEST(parallel_rows, a_stop_request_ends_it_before_any_band) {
  std::atomic<bool> stop{true};
  int ran = 0;
  try {
    parallel_rows(64, 8, 1, CancelToken(&stop), "test rows", [&](cv::Range) { ++ran; });
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::interrupted);
    EXPECT_STREQ(e.what(), "test rows: interrupted");
  }
  EXPECT_EQ(ran, 0);
}

TEST(parallel_rows, refuses_an_empty_band) {
  try {
    parallel_rows(10, 0, 1, [](cv::Range) {});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "row band: must be at least 1 row (got 0)");
  }
}

// The raster buffers' allocator gives what std::vector promises (value-initialised elements,
// copies equal) and a huge buffer on a 2 MiB boundary, where the kernel can map huge pages.
TEST(large_buffer, vectors_are_zeroed_and_huge_ones_start_on_a_2_MiB_boundary) {
  using Doubles = std::vector<double, LargeBufferAllocator<double>>;
  const Doubles huge(std::size_t{3} << 18);  // 6 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(huge.data()) % (std::uintptr_t{2} << 20), 0u);
  EXPECT_EQ(std::count(huge.begin(), huge.end(), 0.0), static_cast<long>(huge.size()));
  Doubles copy = huge;
  copy[12345] = 1.5;
  EXPECT_NE(copy, huge);
  copy[12345] = 0;
  EXPECT_EQ(copy, huge);
  std::vector<std::uint32_t, LargeBufferAllocator<std::uint32_t>> small(100, 7u), empty;
  EXPECT_EQ(std::count(small.begin(), small.end(), 7u), 100);
  empty.push_back(3);
  EXPECT_EQ(empty.back(), 3u);
}

}  // namespace
}  // namespace ifsfx
