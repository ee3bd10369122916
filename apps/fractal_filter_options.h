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
  std::string preset;  // the command's default preset
  std::string colouring;
  bool exact = true;  // --exact (default) or --chaos
  std::string view;
  double margin = 0.05;
  double quality = 64;
  double mix = 0;
  std::string background = "black";
  double drift_amount = 0.05;
  double drift_speed = 0.2;
  std::int64_t loop = 0;  // frames after which the animation repeats, 0 = never
  std::uint64_t seed = 1;
  int threads = 0;

  // The fractal engine's settings of these options, view and background parsed (errors name the
  // flags); the command adds its own (animation, interpolation). The engine checks the rest.
  video::FractalSettings settings() const;
};

// Registers --preset, --colouring, --exact/--chaos, --view, --margin, --quality, --mix and
// --background in the help group "Fractal", --drift-amount, --drift-speed and --loop in
// "Animation", and --seed and --threads.
void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args);

}  // namespace ifsfx::app
