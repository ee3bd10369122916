// SPDX-License-Identifier: Apache-2.0
// Cooperative cancellation of long library computations (steal maps, the exact descent, superIFS
// burn-in, collage fits). The caller owns a stop flag (the command line sets it from SIGINT and
// SIGTERM); the library polls it between units of work of bounded cost and throws
// Error{interrupted}, so that a stop request is honoured within a fraction of a second and no
// half result escapes. Libraries never install signal handlers themselves.
//   std::atomic<bool> stop{false};
//   options.cancel = CancelToken(&stop);   // in the callee: options.cancel.check("steal map");
#pragma once

#include <atomic>

namespace ifsfx {

// A read-only view of a caller's stop flag; the default token never asks to stop. Cheap to copy
// and to poll (one relaxed atomic load), safe to poll from worker threads.
class CancelToken {
 public:
  CancelToken() = default;
  explicit CancelToken(const std::atomic<bool>* flag) : flag_(flag) {}

  bool requested() const noexcept {
    return flag_ != nullptr && flag_->load(std::memory_order_relaxed);
  }
  // The flag watched (null for a token that never stops), for loops that poll a flag.
  const std::atomic<bool>* flag() const noexcept { return flag_; }

  // Throws Error{interrupted} "WHAT: interrupted" when a stop was requested.
  void check(const char* what) const;

  // Two tokens are equal when they watch the same flag (settings compared for equality hold one).
  friend bool operator==(const CancelToken&, const CancelToken&) = default;

 private:
  const std::atomic<bool>* flag_ = nullptr;
};

}  // namespace ifsfx
