// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the flame XML reader and writer (tools/run-fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/flame_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ifsfx::fuzz::flame_xml({reinterpret_cast<const char*>(data), size});
  return 0;
}
