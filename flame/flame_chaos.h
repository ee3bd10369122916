// SPDX-License-Identifier: Apache-2.0
// A flame through ifsfx's chaos game (docs/flames.md, "The paper's modes"; docs/design.md §10):
// its attractor, its fractal tops and colour stealing, with the flame's camera. The orbit runs
// through the flame's xforms (pre-affine, variations, post, the final xform on the plotted copy,
// xaos, weights: flame/xform_eval.h); each step's xform index σk is a symbol of the point's
// address, so tops (paper eq. 7: where pieces overlap the highest address wins) and colour
// stealing (paper §4: the colouring IFS G driven by the same σk) carry over unchanged. The colour
// coordinate of the flame look is not used: its role is taken by G's orbit.
//
// The coverage policy is the affine chaos game's (docs/design.md §2). A flame whose xforms are
// plain `linear` maps walks as its affine IFS (affine_ifs) does, the same lanes, generators and
// burn-in (ifs/detail/walkers.h), and gives its bytes in every mode; any other flame walks in
// lockstep batches through the renderer's batch forms (flame/detail/flame_walk.h).
//
// Refused: the exact descent (it follows f_n⁻¹, and a flame's xforms have no inverse), the torus
// of a seamless tile, and a colouring IFS whose map count is not the flame's xform count.
//
//   const StealMap T = flame_steal_map(flame, default_colouring(flame.xforms.size()), {1024, 768});
//   const cv::Mat tops = flame_tops(flame, {1024, 768}, {}, {}, true);
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "flame/flame.h"
#include "ifs/ifs.h"
#include "ifs/render.h"
#include "ifs/sampling.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"
#include "ifs/view.h"

namespace ifsfx::flame {

// The raster a flame's chaos-game pictures are drawn on, in ifsfx's IFS plane (y up: the flame
// plane flipped, S(x, y) = (x, −y)): sampling.view when given, else the flame camera's rectangle
// at `size` (the framing kept, the scale following the width, as render_flame does; the camera's
// `rotate` turns the plotted points). Never wraps.
Viewport flame_viewport(const Flame& flame, cv::Size size, const Sampling& sampling = {});

// The flame as the affine IFS it is, when it is one: every xform's variations are one `linear` of
// weight 1 (or none), no post-affine map, no pre_/post_ terms, no final xform, no xaos; the maps
// are the pre-affine maps in the IFS plane (S∘A∘S), the probabilities the weights.
std::optional<Ifs> affine_ifs(const Flame& flame);

// The attractor: 255 where a point landed (render_attractor's picture), CV_8UC1.
cv::Mat flame_attractor(const Flame& flame, cv::Size size, const Sampling& sampling = {},
                        RenderStats* stats = nullptr);

// The first two symbols (xform indices) of each pixel's top address, by the chaos game's 32-bit
// keys and the coverage policy (top_symbols with exact = false).
TopSymbols flame_top_symbols(const Flame& flame, cv::Size size, const TopsOptions& options = {});

// The tops picture (tops_picture): xform n coloured palette_colour(n, N), `background` off the
// attractor; BGRA float with `alpha` (the coverage), else BGR.
cv::Mat flame_tops(const Flame& flame, cv::Size size, const TopsOptions& options,
                   const Rgb& background, bool alpha, TopsPictureStats* stats = nullptr);

// The steal map T = π_G(τ(x)) (compute_steal_map with exact = false): each pixel's top address,
// followed through G, `G` on the unit square with one map per xform. A flame whose xforms are
// affine (affine_ifs) takes T at the pixel centre as the affine chaos game does; any other takes
// g_σ1 ∘ … ∘ g_σK(c) of the winning point's whole key (c the fixed point of g_σK): the point's own
// coupled orbit, which needs no inverse. Throws Error{invalid_ifs} when G's map count differs.
StealMap flame_steal_map(const Flame& flame, const Ifs& G, cv::Size size,
                         const StealMapOptions& options = {}, StealMapStats* stats = nullptr);

// The refusals every door shares: Error{invalid_argument} for `exact` ("exact: ... (got a
// flame)") and for `seamless`.
void check_flame_chaos(const Sampling& sampling, bool exact);

}  // namespace ifsfx::flame
