// SPDX-License-Identifier: Apache-2.0
#include "ifs/cancel.h"

#include <string>

#include "ifs/error.h"

namespace ifsfx {

void CancelToken::check(const char* what) const {
  if (requested()) throw Error(ErrorKind::interrupted, std::string(what) + ": interrupted");
}

}  // namespace ifsfx
