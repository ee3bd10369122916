// SPDX-License-Identifier: Apache-2.0
// A still in any render mode (run/render_modes.h), from data: the IFS or flame, the source
// picture, the colouring IFS. A flame draws its attractor, tops and steal maps through the chaos
// game (flame/flame_chaos.h), its measure as flam3 does (flame/render.h). Returns pixels; writing
// or encoding them is the caller's (the command writes a file, the studio answers with PNG bytes,
// Python returns an array), so all three make the same picture from the same request.
//
//   const StillResult still = render_still(fern, {.mode = RenderMode::tops, .size = {512, 512}});
//   write_image("fern-tops.png", still.image);
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "engine/drawing.h"
#include "ifs/ifs.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tiles.h"
#include "run/render_modes.h"

namespace ifsfx::app {

struct StillJob {
  RenderMode mode = RenderMode::measure;
  cv::Size size{1024, 1024};
  // The sampling (view, margin, quality, seed, threads, cancel, seamless) and the measure mode's
  // tone map; the library's defaults.
  RenderOptions options;
  bool exact = true;             // tops, steal: the exact descent (true) or the chaos game; a
                                 // flame: refused (its xforms have no inverse)
  bool second_symbol = false;    // tops: mix in the second symbol's colour
  Rgb background;                // tops, steal: off the attractor (black)
  bool alpha = true;             // tops, steal: the coverage as a fourth channel
  cv::Mat source;                // steal: the picture whose colours are stolen (required)
  std::optional<Ifs> colouring;  // steal: G on the source's unit square, one map per map or
                                 // xform of F; none: default_colouring
  // With options.sampling.seamless: the periods and offset of the picture (one tile by default).
  TileLayout layout;
};

struct StillResult {
  cv::Mat image;                // CV_8UC1 (attractor), CV_32FC3 (measure), BGR(A) otherwise
  RenderStats stats;            // points, seconds, coverage, the view shown
  std::optional<StealMap> map;  // steal: the map that coloured the picture (laid out)
  StealMapStats steal;          // steal: how the map was made
};

// The picture of `F` in job.mode. Throws Error{invalid_argument} for a steal without a source,
// or a flame with job.exact or seamless, Error{interrupted} when job.options.sampling.cancel asks
// to stop, and what the renderers throw.
StillResult render_still(const engine::Drawing& F, const StillJob& job);

}  // namespace ifsfx::app
