// SPDX-License-Identifier: Apache-2.0
// The chaos game of the renderers, baseline side: the fixed split of a point budget into chunks,
// the seeds of a chunk's lanes, and the tables a WalkSpec points into. The walks themselves are
// the kernels of walk_kernels.h, chosen per CPU. Private to ifs/.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ifs/chaos_game.h"
#include "ifs/detail/walk_kernels.h"
#include "ifs/ifs.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::detail {

// Points a chunk plots; fixed, so the split of work is a function of the point count only, and
// every chunk is seeded from (seed, chunk): results never depend on the thread count.
inline constexpr std::uint64_t kChunkPoints = std::uint64_t{1} << 22;

// A walk two orders of magnitude slower per point than the affine kernels takes chunks this
// much smaller, so that a picture is still many chunks for the workers to share: an affine IFS
// drawn as a flame that does not contract (flame/flame_chaos.h; any other flame walks in batches
// of its own size, flame/detail/flame_walk.h).
inline constexpr std::uint64_t kSlowChunkPoints = std::uint64_t{1} << 16;

inline std::uint64_t chunk_count(std::uint64_t points, std::uint64_t per_chunk = kChunkPoints) {
  return std::max<std::uint64_t>(1, (points + per_chunk - 1) / per_chunk);
}

inline std::uint64_t chunk_size(std::uint64_t points, std::uint64_t chunk,
                                std::uint64_t per_chunk = kChunkPoints) {
  const std::uint64_t begin = chunk * per_chunk;
  return begin >= points ? 0 : std::min(per_chunk, points - begin);
}

// The tables of one walk — the IFS's maps as structure of arrays, its alias tables (MapPicker),
// the palette coordinates c_n = n / (N − 1) of its maps in 16-bit fixed point (docs/design.md §4) —
// and the WalkSpec that points into them, with the viewport's pixel mapping. Not copyable: the
// spec points into it.
class WalkTables {
 public:
  // `burn_in` steps per lane before plotting; keys of `key_bits` bits per symbol (tops).
  WalkTables(const Ifs& ifs, const Viewport& viewport, int burn_in, int key_bits = 1);
  WalkTables(const WalkTables&) = delete;
  WalkTables& operator=(const WalkTables&) = delete;

  const WalkSpec& spec() const { return spec_; }

 private:
  std::vector<double> a_, b_, c_, d_, e_, f_;
  MapPicker pick_;
  std::vector<std::uint32_t> palette_;
  WalkSpec spec_{};
};

// One lane's xoshiro256+ (Blackman and Vigna) on the baseline side: the generator of the walk
// kernels' lanes (walk_kernels_common.inl keeps its own copy per instruction set), for a walker
// that must draw what a kernel lane draws — a flame's, flame/flame_chaos.cpp, which gives an
// affine IFS's bytes when its xforms are the IFS's maps.
class LaneRng {
 public:
  explicit LaneRng(const std::uint64_t (&state)[4]) : s_{state[0], state[1], state[2], state[3]} {}
  std::uint64_t next() {
    const std::uint64_t result = s_[0] + s_[3];
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = (s_[3] << 45) | (s_[3] >> 19);
    return result;
  }
  // A uniform coordinate in [0, 1) from one draw (53 bits), as the kernels start a lane.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t s_[4];
};

// The maps as structure-of-arrays for run_chunk.
struct MapTable {
  std::vector<double> a, b, c, d, e, f;
  explicit MapTable(const Ifs& ifs) {
    for (const auto& m : ifs.maps) {
      a.push_back(m.a), b.push_back(m.b), c.push_back(m.c);
      d.push_back(m.d), e.push_back(m.e), f.push_back(m.f);
    }
  }
};

// Runs the walkers of one chunk for chaos_game_samples (points in the plane, not on a raster).
// `visit(lane, x, y, map)` is called for every plotted point (after each lane's burn-in), lanes
// interleaved step by step.
template <class Visit>
void run_chunk(const MapTable& maps, const MapPicker& pick, std::uint64_t seed, std::uint64_t chunk,
               std::uint64_t points, int burn_in, Visit&& visit) {
  Rng rng(stream_seed(seed, chunk));
  double x[kLanes], y[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    x[lane] = rng.uniform();
    y[lane] = rng.uniform();
  }
  const double *a = maps.a.data(), *b = maps.b.data(), *c = maps.c.data();
  const double *d = maps.d.data(), *e = maps.e.data(), *f = maps.f.data();
  for (int step = 0; step < burn_in; ++step)
    for (int lane = 0; lane < kLanes; ++lane) {
      const std::uint32_t n = pick(rng.next());
      const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
      y[lane] = c[n] * x[lane] + d[n] * y[lane] + f[n];
      x[lane] = nx;
    }
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t step = 0; step < steps; ++step)
    for (int lane = 0; lane < kLanes; ++lane) {
      const std::uint32_t n = pick(rng.next());
      const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
      y[lane] = c[n] * x[lane] + d[n] * y[lane] + f[n];
      x[lane] = nx;
      visit(lane, nx, y[lane], n);
    }
  for (int lane = 0; lane < static_cast<int>(points % kLanes); ++lane) {
    const std::uint32_t n = pick(rng.next());
    const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
    y[lane] = c[n] * x[lane] + d[n] * y[lane] + f[n];
    x[lane] = nx;
    visit(lane, nx, y[lane], n);
  }
}

}  // namespace ifsfx::detail
