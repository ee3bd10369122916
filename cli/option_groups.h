// SPDX-License-Identifier: Apache-2.0
// The groups of flags that several commands share, registered on a CLI11 command and bound to the
// run layer's argument structs: the fractal of a filter (`filter`, `cam`, `farm filter`), the
// filter's picture and encoding (`filter`, `farm filter`), a texture (`texture`, `farm texture`)
// and seamless tiles (`render`, `texture`).
#pragma once

#include <memory>

#include <CLI/CLI.hpp>

#include "run/filter_options.h"
#include "run/fractal_filter_options.h"
#include "run/seamless_options.h"
#include "run/texture_options.h"

namespace ifsfx::app {

// Registers --preset, --colouring, --exact/--chaos, --view, --margin, --quality, --mix and
// --background in the help group "Fractal", --drift-amount, --drift-speed and --loop in
// "Animation", and --seed and --threads.
void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args);

// Registers the options (all but INPUT, -o, --preview, --frames, -q) on `cmd`, writing to `args`.
void add_filter_options(CLI::App& cmd, const std::shared_ptr<FilterArgs>& args);

// Registers the options (all but SUPERPRESET, -o, --frames and --frame-range) on `cmd`, writing
// to `args`.
void add_texture_options(CLI::App& cmd, const std::shared_ptr<TextureArgs>& args);

// Registers --seamless, --tiles and --tile-offset on `cmd`.
void add_seamless_options(CLI::App& cmd, SeamlessArgs& args);

}  // namespace ifsfx::app
