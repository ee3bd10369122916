// SPDX-License-Identifier: Apache-2.0
// The render modes of a still, defined once: their names, what each takes besides the sampling,
// and the refusal of options a mode would ignore. The command line, the studio and the Python
// module all read this table; render_still (run/render_still.h) renders each mode.
//
// To add a mode: a value of RenderMode, its row in render_modes.cpp, its case in
// render_still.cpp, and its tests (docs/design.md §10, "How to add a render mode").
#pragma once

#include <span>
#include <string>

namespace ifsfx::app {

enum class RenderMode {
  attractor,  // the set: 255 where a point landed
  measure,    // the invariant measure, log-density, coloured by map
  tops,       // each pixel coloured by the first symbol of its top address (eq. 7)
  steal,      // colours stolen from a source image through the colouring IFS (paper §4)
};

// What a mode takes besides the shared sampling.
struct RenderModeInfo {
  RenderMode mode;
  const char* name;
  const char* help;            // one line, for --help and docstrings
  bool source = false;         // an image to steal colours from (required)
  bool colouring = false;      // the colouring IFS G
  bool save_map = false;       // the steal map can be saved with the picture
  bool map_method = false;     // top addresses by the exact descent or the chaos game
  bool second_symbol = false;  // the second symbol's colour mixed in
  bool background = false;     // a colour off the attractor; alpha where the format has it
  bool flames = false;  // renders a fractal flame too: its measure as flam3 does (flame/render.h),
                        // the others through the chaos game (flame/flame_chaos.h)
};

// Every mode, in the order the help lists them.
std::span<const RenderModeInfo> render_modes();
const RenderModeInfo& render_mode_info(RenderMode mode);
inline const char* to_string(RenderMode mode) {
  return render_mode_info(mode).name;
}

// "attractor, measure, tops or steal".
std::string render_mode_names();

// The mode named `text` (any case). Throws Error{invalid_argument}
// "WHAT: attractor, measure, tops or steal (got 'TEXT')".
RenderMode parse_render_mode(const std::string& text, const std::string& what = "mode");

// A per-mode option as a door names it ("--source" on the command line, "source" in Python) and
// whether the request gave it.
struct ModeOption {
  std::string name;
  bool given = false;
};
struct ModeOptions {
  ModeOption source, colouring, save_map, second_symbol, map_method, background;
};

// Refuses an option given to a mode that would ignore it, and the steal mode without a source:
// Error{invalid_argument} "OPTION: only with MODE_WORD tops or steal (got MODE_WORD measure)",
// "SOURCE: MODE_WORD steal needs a source image". `mode_word` is how the door names the mode's
// own option ("--mode", "mode").
void check_mode_options(RenderMode mode, const ModeOptions& options, const std::string& mode_word);

// Refuses a mode that does not render flames (every mode does today): Error{invalid_argument}
// "MODE_WORD NAME: a flame renders in mode ... (got a flame)".
void check_flame_mode(RenderMode mode, const std::string& mode_word);

}  // namespace ifsfx::app
