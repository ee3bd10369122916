// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the native TOML preset reader (tools/run-fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ifsfx::fuzz::preset_toml({reinterpret_cast<const char*>(data), size});
  return 0;
}
