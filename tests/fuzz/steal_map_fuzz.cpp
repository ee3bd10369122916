// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the steal map file reader, and apply on what it loads (tools/run-fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto scratch = ifsfx::fuzz::scratch_file("steal-map");
  ifsfx::fuzz::steal_map_file({reinterpret_cast<const char*>(data), size}, scratch);
  return 0;
}
