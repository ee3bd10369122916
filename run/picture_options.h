// SPDX-License-Identifier: Apache-2.0
// What the tops and steal modes' pictures share with `ifsfx apply`: the background colour, and
// whether an output format keeps the coverage as alpha (transparent background where it does,
// the background colour elsewhere); and a flame's own background replaced.
#pragma once

#include <string>

#include "flame/flame.h"
#include "ifs/ifs.h"

namespace ifsfx::app {

// "black", "white", "#rrggbb" or "R,G,B" (0..255); throws Error{parse} naming `what`.
Rgb colour_option(const std::string& text, const std::string& what = "--background");

// True for outputs whose format keeps an alpha channel: .png, .tif, .tiff, .exr.
bool format_has_alpha(const std::string& path);

// A flame's measure drawn over another background than its file's: a colour as colour_option
// reads it (opaque), or "transparent" (flam3-render's transparency=1: the empty plane clear,
// each pixel's alpha its density's; a = 0, which only an output with alpha keeps, as the
// callers check). Throws Error{parse} naming `what`.
flame::Rgba flame_background_option(const std::string& text,
                                    const std::string& what = "--background");

}  // namespace ifsfx::app
