// Ctrl-C (SIGINT) and SIGTERM as a request to stop: the running job finishes what it has written
// (a playable movie of the frames done, a finalised recording) instead of dying mid-file.
#pragma once

#include <atomic>
#include <csignal>

namespace ifsfx::app {

// For its lifetime, SIGINT and SIGTERM set stop_flag() (cleared when the guard is made); a second
// signal while the first is being honoured ends the process the default way. The previous
// handlers are restored after.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // Set by a signal; a job may set it too (a window's quit key) and polls it between frames.
  static std::atomic<bool>& stop_flag();

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace ifsfx::app
