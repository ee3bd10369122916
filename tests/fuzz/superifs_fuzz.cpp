// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the superIFS TOML reader (tools/run-fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/superifs_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ifsfx::fuzz::superifs_toml({reinterpret_cast<const char*>(data), size});
  return 0;
}
