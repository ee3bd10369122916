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

// A flame's picture (`name`: the flame's spec or name): the flame, the mode's name, the seed, and
// the command that makes it ("ifsfx render NAME --seed S", with --mode MODE but for the measure,
// which is the flame's default).
std::vector<std::pair<std::string, std::string>> flame_render_metadata(const std::string& name,
                                                                       const std::string& mode,
                                                                       std::uint64_t seed);

}  // namespace ifsfx::app
