// SPDX-License-Identifier: Apache-2.0
// How IFSFX_CPU is read (ifs/cpu.h), apart from the environment, for the tests.
#pragma once

#include <vector>

#include "ifs/cpu.h"

namespace ifsfx::detail {

// The level that `request` (IFSFX_CPU's value, or null when unset) picks among `supported`
// (lowest first): the highest when unset or empty; a level's name in any case; throws
// Error{invalid_argument} naming IFSFX_CPU for a name that is no level, or a level not in
// `supported`.
CpuLevel select_cpu_level(const char* request, const std::vector<CpuLevel>& supported);

}  // namespace ifsfx::detail
