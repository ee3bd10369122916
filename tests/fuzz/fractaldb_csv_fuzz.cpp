// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: FractalDB's category and weight CSV readers (tools/run-fuzz.sh).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ifsfx::fuzz::fractaldb_csv({reinterpret_cast<const char*>(data), size});
  return 0;
}
