// SPDX-License-Identifier: Apache-2.0
// Ctrl-C (SIGINT) and SIGTERM as a request to stop, for every command: long computations poll the
// request through a CancelToken (ifs/cancel.h) and end within a fraction of a second, outputs are
// left as the output policy says (ifs/output_file.h), and main() exits with 128 + the signal's
// number (130 for SIGINT, 143 for SIGTERM).
#pragma once

#include <atomic>
#include <csignal>

#include "ifs/cancel.h"

namespace ifsfx::app {

// For its lifetime, SIGINT and SIGTERM set stop_flag() and record which signal came (both cleared
// when the guard is made). Further signals within kGraceSeconds of the first are ignored (a
// double Ctrl-C must not kill the process before it has removed its temporary files); one after
// that ends the process the default way, an escape hatch should anything fail to stop. The
// previous handlers are restored after.
class StopSignals {
 public:
  static constexpr int kGraceSeconds = 2;

  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // Set by a signal; a job may set it too (a window's quit key) and polls it between frames.
  static std::atomic<bool>& stop_flag();
  // The stop flag as the libraries poll it.
  static CancelToken token() { return CancelToken(&stop_flag()); }
  // The number of the signal that asked to stop (SIGINT, SIGTERM), or 0 when none did.
  static int signal_number();

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace ifsfx::app
