// SPDX-License-Identifier: Apache-2.0
// The chaos game of a flame into its supersampled histogram (Draves & Reckase §3, §5; flame/
// render.h). Fixed chunks of points, each walked from its own start by its own Rng seeded from
// (seed, chunk); every hit adds integers (the palette colour × opacity in 1/65536 steps), so the
// sums, and the picture, do not depend on which thread ran which chunk.
#pragma once

#include <cstdint>
#include <functional>

#include "flame/flame.h"
#include "flame/render_camera.h"
#include "flame/render_tone.h"
#include "ifs/cancel.h"

namespace ifsfx::flame::detail {

struct ChaosRun {
  const Flame* flame = nullptr;
  FlameRaster raster;
  std::uint64_t points = 0;  // iterations plotted (after each walker's burn-in)
  std::uint64_t seed = 1;
  int threads = 0;
  int burn_in = 15;
  bool float_lanes = true;  // FlameRenderOptions::float_lanes
  CancelToken cancel;
  std::function<void(double)> progress;  // fraction of the points done
};

struct ChaosResult {
  FlameHistogram histogram;  // raster.bins_x × raster.bins_y, r g b a sums in hits
  std::uint64_t reseeded = 0;
};

ChaosResult run_chaos_game(const ChaosRun& run);

}  // namespace ifsfx::flame::detail
