// SPDX-License-Identifier: Apache-2.0
#include "cli/stop_signals.h"

#include <time.h>

#include <cstdint>

namespace ifsfx::app {
namespace {

// A signal handler can reach nothing but static storage, and may only touch lock-free atomics:
// these are the one piece of process-wide state the app keeps.
std::atomic<bool> stop_requested{false};
std::atomic<int> stop_signal{0};
std::atomic<std::int64_t> first_signal_ns{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free &&
              std::atomic<std::int64_t>::is_always_lock_free);

// CLOCK_MONOTONIC in nanoseconds; clock_gettime is async-signal-safe (POSIX.1-2008).
std::int64_t now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

extern "C" void on_stop_signal(int signal) {
  const std::int64_t now = now_ns();
  std::int64_t none = 0;
  first_signal_ns.compare_exchange_strong(none, now);
  if (stop_requested.exchange(true)) {
    if (now - first_signal_ns < std::int64_t{StopSignals::kGraceSeconds} * 1'000'000'000) return;
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  stop_signal = signal;
}

}  // namespace

StopSignals::StopSignals() {
  stop_requested = false;
  stop_signal = 0;
  first_signal_ns = 0;
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &old_int_);
  sigaction(SIGTERM, &action, &old_term_);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

std::atomic<bool>& StopSignals::stop_flag() {
  return stop_requested;
}

int StopSignals::signal_number() {
  return stop_signal;
}

}  // namespace ifsfx::app
