// SPDX-License-Identifier: Apache-2.0
// The chaos game of the paper's modes for a flame that is not an affine IFS (flame/flame_chaos.h):
// kBatchLanes walkers in lockstep, each step's walkers grouped by the xform they picked and moved
// through it together (flame/detail/xform_step.h, the renderer's batch forms), each walker
// carrying its address key (σk in the top b bits, docs/design.md §2). A chunk is seeded from
// (seed, chunk) alone, so a picture does not depend on the thread count.
//
//   const FlameWalk walk({.flame = &flame, .to_pixel = viewport.plane_to_pixel(),
//                         .size = viewport.size, .burn_in = 64});
//   walk.walk(seed, chunk, points, [&](const WalkHits& hits) { ... });
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "flame/detail/xform_step.h"
#include "flame/flame.h"
#include "ifs/affine_map.h"
#include "ifs/rng.h"

namespace ifsfx::flame::detail {

// Points each walker of a full chunk plots after its burn-in: 1024 keeps the burn-in of 64 steps
// a sixteenth of the work.
inline constexpr std::uint64_t kWalkerPlots = 1024;
// A walker's steps are bounded by kStepBudget times the steps its points and burn-in take: a
// flame whose orbits always escape (a translation beyond kEscape) would otherwise restart for
// ever, and nothing else ends a walk. Such a walker gives up the points it has left, as the
// renderer's walkers, which stop after a fixed number of steps, plot fewer points where theirs
// escape. A contracting flame never comes near the bound.
inline constexpr std::uint64_t kStepBudget = 16;
// Points a chunk plots (2¹⁸): kBatchLanes walkers of kWalkerPlots.
inline constexpr std::uint64_t kWalkChunkPoints = kWalkerPlots * kBatchLanes;

// The points one step plotted: for hit i, its pixel (row-major on the raster) and its walker's
// address key.
struct WalkHits {
  std::array<long, kStepStride> pixel{};
  std::array<std::uint64_t, kStepStride> key{};
  std::size_t n = 0;
};

struct WalkSetup {
  const Flame* flame = nullptr;
  // The IFS plane (the flame plane flipped, S(x, y) = (x, −y)) to pixels: the viewport's, its
  // a, d, e, f only (no shear), as the affine kernels map a point.
  AffineMap to_pixel;
  std::optional<AffineMap> turn;  // the camera's turn of the plotted points, in the IFS plane
  int width = 0, height = 0;      // the raster, pixels
  int burn_in = 64;               // steps each walker takes unplotted from every (re)start
  // The variations' batch lanes: float (the renderer's default, FlameRenderOptions::float_lanes)
  // or double.
  LaneType lanes = LaneType::f32;
};

class FlameWalk {
 public:
  explicit FlameWalk(const WalkSetup& setup);

  // `points` points of chunk `chunk` of the walk seeded with `seed`: plot(hits) after each step
  // with the points that landed on the raster. Depends on (seed, chunk, points) only. Returns
  // how many of the points were given up (kStepBudget), not plotted.
  std::uint64_t walk(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     const std::function<void(const WalkHits&)>& plot) const;

 private:
  struct Walkers;
  std::size_t move(Walkers& a, Scratch& w, Rng& rng) const;
  void plot_step(Walkers& a, std::size_t plotted, Scratch& w, Rng& rng, WalkHits& hits) const;

  std::vector<XformStep> steps_;
  std::optional<XformStep> final_;
  std::vector<MapPicker> pickers_;
  std::optional<AffineMap> turn_;
  double sx_ = 0, ox_ = 0, sy_ = 0, oy_ = 0;
  int width_ = 0, height_ = 0;
  int burn_in_ = 64;
  int bits_ = 1;
};

}  // namespace ifsfx::flame::detail
