// SPDX-License-Identifier: Apache-2.0
// The metadata `ifsfx render` stores in its images, shared with `ifsfx studio` so that a picture
// from either has the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ifs/preset.h"
#include "ifs/view.h"

namespace ifsfx::app {

// The preset's text and name, the mode's name ("tops"), the seed and the plane rectangle shown.
std::vector<std::pair<std::string, std::string>> render_metadata(const IfsPreset& preset,
                                                                 const std::string& mode,
                                                                 std::uint64_t seed,
                                                                 const Box& view);

}  // namespace ifsfx::app
