// SPDX-License-Identifier: Apache-2.0
// What the engine draws: an affine IFS F (docs/design.md §3) or a fractal flame whose xforms play
// F's part through the chaos game (flame/flame_chaos.h, docs/flames.md). Every door's preset
// becomes one Drawing; the engine, the camera's live drift and the OBS filter ask these functions
// for its steal maps, tops, view and drift, so an IFS and a flame go the same way.
//
//   const Drawing F = load_drawing("art.flame:spiral");
//   const StealMap T = steal_map(F, colouring_for("", F), {1280, 720}, {});
#pragma once

#include <string>
#include <variant>
#include <vector>

#include <opencv2/core.hpp>

#include "engine/drift.h"
#include "flame/flame.h"
#include "ifs/ifs.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"

namespace ifsfx::engine {

using Drawing = std::variant<Ifs, flame::Flame>;

// A preset as any door names it: a flame file (FILE.flame, FILE.flame:NAME, FILE.flame:INDEX;
// flame/flame_file.h) read as a flame, anything else as load_ifs reads it, its warnings appended
// to `warnings`. So `--preset art.flame:NAME` works wherever a preset does. Throws what
// read_flame and load_ifs throw.
Drawing load_drawing(const std::string& spec, const ValidateOptions& options = {},
                     std::vector<std::string>* warnings = nullptr);

// The colouring IFS G for F (load_colouring): default_colouring of F's maps or xforms for an
// empty spec, else `spec` fitted to the unit square, with one map per map or xform of F.
Ifs colouring_for(const std::string& spec, const Drawing& F, const std::string& what = "colouring");

// N: the IFS's maps or the flame's xforms (the final xform is not one of them).
std::size_t map_count(const Drawing& drawing);
// The IFS's or the flame's name.
const std::string& name_of(const Drawing& drawing);

// validate() of an IFS (maps that contract on average will do, as load_ifs accepts a preset); a
// flame needs one xform or more. Throws Error{invalid_ifs} or Error{invalid_argument}.
void check_drawing(const Drawing& drawing);

// compute_steal_map for an IFS; flame_steal_map for a flame, by the chaos game whatever
// options.exact says (its xforms have no inverse to descend by).
StealMap steal_map(const Drawing& drawing, const Ifs& G, cv::Size size,
                   const StealMapOptions& options, StealMapStats* stats = nullptr);

// tops_picture of an IFS or flame_tops of a flame (the chaos game, as steal_map).
cv::Mat tops_picture(const Drawing& drawing, cv::Size size, const TopsOptions& options,
                     const Rgb& background, bool alpha, TopsPictureStats* stats = nullptr);

// The options with the view an animation keeps fixed while the maps move: an IFS's attractor
// auto-framed (sampling.view when given); a flame's camera frames it already, left as it is.
StealMapOptions with_fixed_view(const Drawing& drawing, cv::Size size, StealMapOptions options);

// drift() of an IFS; a flame's xforms' pre-affine maps drifted the same way (their translations
// by `amount` times the width of the camera's view), weights, variations, post maps, colours,
// final xform and camera kept.
Drawing drift(const Drawing& base, double t, const DriftOptions& options);

}  // namespace ifsfx::engine
