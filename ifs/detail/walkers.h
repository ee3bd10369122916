// The chaos-game kernel shared by the renderers: fixed chunks of interleaved walkers, each chunk
// seeded from (seed, chunk) so that results never depend on the thread count. Private to ifs/.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ifs/chaos_game.h"
#include "ifs/ifs.h"
#include "ifs/rng.h"

namespace ifsfx::detail {

// Points a chunk plots; fixed, so the split of work is a function of the point count only.
inline constexpr std::uint64_t kChunkPoints = std::uint64_t{1} << 22;
// Walkers iterated in lockstep inside a chunk: independent dependency chains the CPU overlaps.
inline constexpr int kLanes = 8;

// The maps as structure-of-arrays for the inner loop.
struct MapTable {
  std::vector<double> a, b, c, d, e, f;
  explicit MapTable(const Ifs& ifs) {
    for (const auto& m : ifs.maps) {
      a.push_back(m.a), b.push_back(m.b), c.push_back(m.c);
      d.push_back(m.d), e.push_back(m.e), f.push_back(m.f);
    }
  }
};

inline std::uint64_t chunk_count(std::uint64_t points) {
  return std::max<std::uint64_t>(1, (points + kChunkPoints - 1) / kChunkPoints);
}

inline std::uint64_t chunk_size(std::uint64_t points, std::uint64_t chunk) {
  const std::uint64_t begin = chunk * kChunkPoints;
  return begin >= points ? 0 : std::min(kChunkPoints, points - begin);
}

// Runs the walkers of one chunk. `visit(lane, x, y, map)` is called for every plotted point
// (after each lane's burn-in), lanes interleaved step by step.
template <class Visit>
void run_chunk(const MapTable& maps, const MapPicker& pick, std::uint64_t seed, std::uint64_t chunk,
               std::uint64_t points, int burn_in, Visit&& visit) {
  Rng rng(stream_seed(seed, chunk));
  std::array<double, kLanes> x{}, y{};
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

// Plane → continuous pixel coordinates: px = sx·x + ox, py = sy·y + oy (y up → rows down).
struct PixelMapping {
  double sx, ox, sy, oy;
  double width, height;
  long stride;
};

// The hot loop of the renderers: runs one chunk's walkers and calls plot(lane, pixel, map) for
// every point that lands on the raster. Everything the loop reads is copied into locals first,
// so the compiler keeps it in registers whatever memory `plot` writes.
template <class Plot>
void plot_chunk(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                Plot&& plot) {
  Rng rng(stream_seed(seed, chunk));
  const MapPicker::View pick = picker.view();
  const double *a = maps.a.data(), *b = maps.b.data(), *c = maps.c.data();
  const double *d = maps.d.data(), *e = maps.e.data(), *f = maps.f.data();
  const double sx = mapping.sx, ox = mapping.ox, sy = mapping.sy, oy = mapping.oy;
  const double width = mapping.width, height = mapping.height;
  const long stride = mapping.stride;
  double x[kLanes], y[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    x[lane] = rng.uniform();
    y[lane] = rng.uniform();
  }
  for (int step = 0; step < burn_in; ++step)
    for (int lane = 0; lane < kLanes; ++lane) {
      const std::uint32_t n = pick(rng.next());
      const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
      y[lane] = c[n] * x[lane] + d[n] * y[lane] + f[n];
      x[lane] = nx;
    }
  auto advance = [&](int lane) {
    const std::uint32_t n = pick(rng.next());
    const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
    const double ny = c[n] * x[lane] + d[n] * y[lane] + f[n];
    x[lane] = nx;
    y[lane] = ny;
    const double px = sx * nx + ox, py = sy * ny + oy;
    // Non-short-circuit tests: one well-predicted branch instead of four.
    if ((px >= 0) & (px < width) & (py >= 0) & (py < height))
      plot(lane, static_cast<long>(py) * stride + static_cast<long>(px), n);
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t step = 0; step < steps; ++step) {
#pragma GCC unroll 8
    for (int lane = 0; lane < kLanes; ++lane) advance(lane);
  }
  for (int lane = 0; lane < static_cast<int>(points % kLanes); ++lane) advance(lane);
}

}  // namespace ifsfx::detail
