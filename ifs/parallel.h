// SPDX-License-Identifier: Apache-2.0
// The one parallel helper of the libraries: a fixed list of chunks handed out to worker threads.
// Results must depend only on the chunk index, never on which thread ran it, so that the same
// seed gives the same pixels for any thread count (docs/style.md rule 5).
#pragma once

#include <cstddef>
#include <functional>

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

}  // namespace ifsfx
