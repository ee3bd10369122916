// SPDX-License-Identifier: Apache-2.0
// The OBS filter's properties as plain values, and the engine settings they stand for: the
// options of `ifsfx filter` (run/filter_options.h, run/fractal_filter_options.h) under the
// same names, so that a filter set up in OBS is the command `ifsfx filter` with those flags.
// Free of libobs (plugins/obs/ifsfx_obs.cpp reads obs_data into PropertyValues).
#pragma once

#include <cstdint>
#include <string>

#include "engine/fractal_engine.h"

namespace ifsfx::obs {

// What the filter shows: the frame coloured through the steal map of F (colour stealing, paper
// §6), or the tops picture of F (paper §3) over the frame by `mix` and `background`.
enum class Mode { steal, tops };

// The dialog's values, one per property, under the property's name.
struct PropertyValues {
  std::string preset = "sierpinski-triangle";         // a shipped name ...
  std::string preset_file;                            // ... unless a .toml/.ifs/.csv file is picked
  std::string mode = "steal";                         // steal | tops
  std::string colouring;                              // --colouring ("" = a tiling of the frame)
  std::string view;                                   // --view x0,y0,x1,y1 ("" = auto-framed)
  double mix = 0;                                     // --mix
  std::string background = "black";                   // --background
  std::string animate = "none";                       // --animate none | drift | superifs
  double drift_amount = engine::kDefaultDriftAmount;  // --drift-amount
  double drift_speed = engine::kDefaultDriftSpeed;    // --drift-speed
  std::string superifs = "paper-fig4";                // --superifs
  std::int64_t buffers = 3;                           // --buffers (V)
  std::int64_t keyframe_interval = engine::kDefaultKeyframeInterval;  // --keyframe-interval
  std::int64_t loop = 0;  // --loop, in frames of OBS's frame rate
  std::int64_t seed = 1;  // --seed
  bool exact = true;      // --exact / --chaos
};

struct PluginSettings {
  Mode mode = Mode::steal;
  engine::FractalSettings engine;
};

// The settings of `values`, parsed and the presets loaded (as data, the engine's drawing and
// colouring IFSs); throws ifsfx::Error naming the property ("view: ...") for a value that cannot
// be parsed, a preset that cannot be loaded and a loop without an animation.
PluginSettings settings_of(const PropertyValues& values);

// Loads the fractal of `settings` and checks what does not depend on the frame size, as the
// engine's first step does; throws ifsfx::Error with the engine's one-line message. Cheap (a
// file or a shipped preset is read, nothing is rendered): OBS's update calls it at once, so a bad
// preset is shown in the dialog as it is typed.
void check_settings(const PluginSettings& settings);

}  // namespace ifsfx::obs
