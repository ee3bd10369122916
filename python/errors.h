// SPDX-License-Identifier: Apache-2.0
// The library's errors as Python exceptions, with its messages ("what: rule (got X)"):
//   parse, invalid_ifs, invalid_argument, unsupported  ->  ValueError
//   not_found                                           ->  FileNotFoundError (an OSError)
//   io, device                                          ->  OSError
//   interrupted                                         ->  KeyboardInterrupt
// And the long computations run with the GIL released, stoppable by Ctrl-C (run_released).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <pybind11/pybind11.h>

#include "ifs/cancel.h"

namespace ifsfx::python {

namespace py = pybind11;

// Registers the translation above with the module.
void register_errors(py::module_& m);

// How often a computation's caller looks for a pending signal (Ctrl-C) while it waits. The
// library polls its cancel token between units of work of a fraction of a second, so that a
// KeyboardInterrupt arrives within half a second.
inline constexpr std::chrono::milliseconds kSignalPoll{40};

// Runs `work(token)` on a thread of its own with the GIL released, and returns its result. The
// caller waits without the GIL (other Python threads run) and, every kSignalPoll, takes the GIL
// back briefly to run Python's signal handlers (PyErr_CheckSignals, which only the main thread
// does): when a handler raises (KeyboardInterrupt on SIGINT), the token asks the work to stop,
// the work's Error{interrupted} is dropped and the handler's exception is raised instead. The
// work must not touch Python objects.
//   cv::Mat image = run_released([&](const CancelToken& cancel) { return render(..., cancel); });
// With `stop` as the stop flag: for work whose library object polls a flag it was made with
// (the Filter's engine); the caller clears it after a stop.
template <class Work>
auto run_released(Work&& work, std::atomic<bool>& stop) {
  using Result = decltype(work(CancelToken{}));
  const CancelToken token(&stop);
  std::optional<Result> result;
  std::exception_ptr error;
  bool done = false, raised = false;
  std::mutex mutex;
  std::condition_variable finished;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        result.emplace(work(token));
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    for (;;) {
      std::unique_lock lock(mutex);
      if (finished.wait_for(lock, kSignalPoll, [&] { return done; })) break;
      lock.unlock();
      if (!raised) {
        const py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {  // the exception stays set in this thread
          raised = true;
          stop = true;
        }
      }
    }
    worker.join();
  }
  if (raised) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

template <class Work>
auto run_released(Work&& work) {
  std::atomic<bool> stop{false};
  return run_released(std::forward<Work>(work), stop);
}

}  // namespace ifsfx::python
