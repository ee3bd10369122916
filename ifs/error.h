// SPDX-License-Identifier: Apache-2.0
// The one error type of the ifsfx libraries. Libraries never print or exit: they throw an
// ifsfx::Error, and the command line turns it into one line on stderr and a non-zero exit code.
//
// Messages follow the form "what: rule (got X)" and start with the culprit (a file and line, a
// device, an option) so that one line is enough to act on.
#pragma once

#include <stdexcept>
#include <string>

namespace ifsfx {

// What kind of failure; tests check the kind as well as the message.
enum class ErrorKind {
  parse,        // malformed preset, map file or option value: message names file and line
  invalid_ifs,  // non-contractive map, bad probabilities, NaN/inf coefficient, map count mismatch
  invalid_argument,  // a value out of range: size, thread count, frame range, ...
  not_found,         // unknown preset name, missing file or device
  io,                // a read or write that failed: unreadable, unwritable, disk full, corrupt data
  unsupported,       // a format, codec, extension or device capability we cannot handle
  device,            // a V4L2 device fault: busy, vanished mid-stream
  interrupted,       // work stopped by a signal; what was done has been kept
};

const char* to_string(ErrorKind kind) noexcept;

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const noexcept { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace ifsfx
