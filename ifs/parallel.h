// SPDX-License-Identifier: Apache-2.0
// The parallel helpers of the libraries: a fixed list of chunks handed out to worker threads
// (parallel_for), and an image's rows in fixed bands (parallel_rows, built on it). Results must
// depend only on the chunk index, never on which thread ran it, so that the same seed gives the
// same pixels for any thread count (docs/style.md rule 5).
#pragma once

#include <cstddef>
#include <functional>

#include <opencv2/core/types.hpp>

#include "ifs/cancel.h"

namespace ifsfx {

// The most worker threads any computation is given (the command line's --threads cap): more than
// any machine's cores, few enough that per-thread buffers and a codec's per-thread frames cannot
// eat the memory.
inline constexpr int kMaxThreads = 256;

// Number of worker threads for a requested count: 0 means all hardware threads (at most
// kMaxThreads). Throws Error{invalid_argument} "threads: ..." below 0 or above kMaxThreads.
int resolve_threads(int requested);

// Runs fn(chunk, worker) for chunk = 0..chunks-1 on `threads` workers (0 = all cores). Worker
// indices are in [0, workers) where workers = min(threads, chunks), so per-worker scratch can be
// allocated up front with `worker_count`. An exception thrown by fn is rethrown here once all
// workers have stopped.
void parallel_for(std::size_t chunks, int threads,
                  const std::function<void(std::size_t chunk, int worker)>& fn);

// The number of workers parallel_for will use for these arguments.
int worker_count(std::size_t chunks, int threads);

// The rows [0, rows) of an image in fixed bands of `band` rows (the last one shorter), the way
// OpenImageIO's parallel_image splits an ROI: fn(range) for each band on `threads` workers (0 =
// all cores). The split depends on rows and band only, never on the threads, so that a result
// written band by band is the same for any thread count. Throws Error{invalid_argument} for a
// band below 1 row.
//   parallel_rows(out.rows, 32, threads, [&](cv::Range rows) { ... out.rowRange(rows) ... });
void parallel_rows(int rows, int band, int threads, const std::function<void(cv::Range rows)>& fn);
// The same, polling `cancel` before each band: a stop request ends the loop with
// Error{interrupted} "WHAT: interrupted" (CancelToken::check).
void parallel_rows(int rows, int band, int threads, const CancelToken& cancel, const char* what,
                   const std::function<void(cv::Range rows)>& fn);
// The same over `planes` images of `rows` rows each (the superIFS buffers): fn(plane, range) for
// every band of every plane, plane by plane.
void parallel_rows(std::size_t planes, int rows, int band, int threads, const CancelToken& cancel,
                   const char* what,
                   const std::function<void(std::size_t plane, cv::Range rows)>& fn);

}  // namespace ifsfx
