// SPDX-License-Identifier: Apache-2.0
// The options `ifsfx filter` and `ifsfx cam` share: the fractal a frame is coloured through (the
// drawing IFS F, the colouring IFS G, the view, how the steal map is made), how the frame shows
// through it, the drift animation, the seed and the worker threads.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/fractal_engine.h"

namespace ifsfx::app {

struct FractalFilterArgs {
  // The flags bind here, the engine's defaults but for the fractal; the presets, the view and the
  // background are read by settings().
  engine::FractalSettings engine;
  std::string preset = engine::kDefaultPreset;  // F: a shipped name, a .toml/.ifs path, FILE:NAME,
                                                // or a flame: FILE.flame[:NAME|:INDEX]
  std::string colouring;  // G: a preset fitted to the unit square; "" = a tiling
  std::string view;
  std::string background = "black";
  // The exact descent asked for by name (`--exact` on the command line, "exact" in a studio job):
  // refused for a flame, whose steal map always comes from the chaos game. `exact_name` is the
  // flag or field the message names.
  bool exact_given = false;
  std::string exact_name = "--exact";

  // The fractal engine's settings of these options: the presets loaded (their warnings, one line
  // each, added to `warnings`), view and background parsed (errors name the flags); the caller
  // adds its own (the stop flag, animation, interpolation). The engine checks the rest.
  engine::FractalSettings settings(std::vector<std::string>* warnings = nullptr) const;
  // The same with F and G given as data (a door that holds them: the studio), the presets unread.
  // Both refuse a named exact descent for a flame.
  engine::FractalSettings settings_of(engine::Drawing drawing, std::optional<Ifs> colouring) const;
};

// A flame's steal map always comes from the chaos game, so an exact descent asked for by name
// (`named`: the flag or field was given) would do nothing: refused, the message naming `name`.
void refuse_named_exact(const engine::Drawing& drawing, bool exact, bool named,
                        std::string_view name);

}  // namespace ifsfx::app
