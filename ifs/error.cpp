// SPDX-License-Identifier: Apache-2.0
#include "ifs/error.h"

namespace ifsfx {

const char* to_string(ErrorKind kind) noexcept {
  switch (kind) {
    case ErrorKind::parse:
      return "parse error";
    case ErrorKind::invalid_ifs:
      return "invalid IFS";
    case ErrorKind::invalid_argument:
      return "invalid argument";
    case ErrorKind::not_found:
      return "not found";
    case ErrorKind::io:
      return "I/O error";
    case ErrorKind::unsupported:
      return "unsupported";
    case ErrorKind::device:
      return "device error";
    case ErrorKind::interrupted:
      return "interrupted";
  }
  return "error";
}

}  // namespace ifsfx
