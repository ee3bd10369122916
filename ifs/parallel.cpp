// SPDX-License-Identifier: Apache-2.0
#include "ifs/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx {

int resolve_threads(int requested) {
  if (requested < 0 || requested > kMaxThreads)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("threads: must be 0 (all cores) to {} (got {})", kMaxThreads, requested));
  if (requested > 0) return requested;
  return static_cast<int>(
      std::clamp(std::thread::hardware_concurrency(), 1u, static_cast<unsigned>(kMaxThreads)));
}

int worker_count(std::size_t chunks, int threads) {
  const auto t = static_cast<std::size_t>(resolve_threads(threads));
  return static_cast<int>(std::max<std::size_t>(1, std::min(t, chunks)));
}

void parallel_for(std::size_t chunks, int threads,
                  const std::function<void(std::size_t, int)>& fn) {
  const int workers = worker_count(chunks, threads);
  if (workers == 1) {
    for (std::size_t c = 0; c < chunks; ++c) fn(c, 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](int worker) {
    for (;;) {
      const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
      if (c >= chunks || failed.load(std::memory_order_relaxed)) return;
      try {
        fn(c, worker);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
    }
  };
  std::vector<std::jthread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  pool.clear();  // joins
  if (error) std::rethrow_exception(error);
}

void parallel_rows(std::size_t planes, int rows, int band, int threads, const CancelToken& cancel,
                   const char* what,
                   const std::function<void(std::size_t plane, cv::Range rows)>& fn) {
  if (band < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("row band: must be at least 1 row (got {})", band));
  const auto bands = static_cast<std::size_t>((std::max(rows, 0) + band - 1) / band);
  parallel_for(planes * bands, threads, [&](std::size_t chunk, int) {
    cancel.check(what);
    const int row0 = static_cast<int>(chunk % bands) * band;
    fn(chunk / bands, cv::Range(row0, std::min(rows, row0 + band)));
  });
}

void parallel_rows(int rows, int band, int threads, const CancelToken& cancel, const char* what,
                   const std::function<void(cv::Range rows)>& fn) {
  parallel_rows(1, rows, band, threads, cancel, what,
                [&](std::size_t, cv::Range range) { fn(range); });
}

void parallel_rows(int rows, int band, int threads, const std::function<void(cv::Range rows)>& fn) {
  parallel_rows(rows, band, threads, CancelToken(), "rows", fn);
}

}  // namespace ifsfx
