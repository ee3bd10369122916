// SPDX-License-Identifier: Apache-2.0
// The options `ifsfx filter` and `ifsfx cam` share: the fractal a frame is coloured through (the
// drawing IFS F, the colouring IFS G, the view, how the steal map is made), how the frame shows
// through it, the drift animation, the seed and the worker threads.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "video/fractal_engine.h"

namespace ifsfx::app {

struct FractalFilterArgs {
  // The flags bind here, the engine's defaults but for the command's preset; view and background
  // are parsed by settings().
  video::FractalSettings engine;
  std::string view;
  std::string background = "black";

  // The fractal engine's settings of these options, view and background parsed (errors name the
  // flags) and Ctrl-C's stop flag set; the command adds its own (animation, interpolation). The
  // engine checks the rest.
  video::FractalSettings settings() const;
};

// Registers --preset, --colouring, --exact/--chaos, --view, --margin, --quality, --mix and
// --background in the help group "Fractal", --drift-amount, --drift-speed and --loop in
// "Animation", and --seed and --threads.
void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args);

}  // namespace ifsfx::app
