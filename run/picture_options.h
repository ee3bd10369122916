// SPDX-License-Identifier: Apache-2.0
// What the tops and steal modes' pictures share with `ifsfx apply`: the background colour, and
// whether an output format keeps the coverage as alpha (transparent background where it does,
// the background colour elsewhere).
#pragma once

#include <string>

#include "ifs/ifs.h"

namespace ifsfx::app {

// "black", "white", "#rrggbb" or "R,G,B" (0..255); throws Error{parse} naming `what`.
Rgb colour_option(const std::string& text, const std::string& what = "--background");

// True for outputs whose format keeps an alpha channel: .png, .tif, .tiff, .exr.
bool format_has_alpha(const std::string& path);

}  // namespace ifsfx::app
