// SPDX-License-Identifier: Apache-2.0
// Whether a call ended by a stop request: it threw ifsfx::Error{interrupted} (ifs/cancel.h).
#pragma once

#include "ifs/error.h"

namespace ifsfx::testing {

template <class F>
bool interrupted(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.kind() == ErrorKind::interrupted;
  }
  return false;
}

}  // namespace ifsfx::testing
