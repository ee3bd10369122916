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
#include "ifs/view.h"

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

// The mapping of a viewport (its plane → pixel transform has no rotation).
inline PixelMapping pixel_mapping(const Viewport& v) {
  const AffineMap m = v.plane_to_pixel();
  return {m.a,
          m.e,
          m.d,
          m.f,
          static_cast<double>(v.size.width),
          static_cast<double>(v.size.height),
          v.size.width};
}

// xoshiro256+: the renderers' per-lane generator. Plain 64-bit shifts, xors and adds, so four
// lanes run in one AVX2 register (walkers_avx2.h) and the scalar loop below is its bit-exact
// reference. Each lane is seeded from (seed, chunk, lane).
struct LaneRng {
  std::uint64_t s[4];
  void seed(std::uint64_t seed, std::uint64_t chunk, int lane) {
    std::uint64_t z = stream_seed(seed, chunk * kLanes + static_cast<std::uint64_t>(lane));
    for (auto& word : s) word = z = mix64(z + 0x9e3779b97f4a7c15ULL);
  }
  std::uint64_t next() {
    const std::uint64_t result = s[0] + s[3];
    const std::uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = (s[3] << 45) | (s[3] >> 19);
    return result;
  }
};

// A uniform start in [0,1)² drawn from a lane's generator.
inline double start_coordinate(LaneRng& rng) {
  return static_cast<double>(rng.next() >> 11) * 0x1.0p-53;
}

// The hot loop of the renderers: runs one chunk's walkers and calls plot(lane, pixel, map) for
// every point that lands on the raster, lanes interleaved step by step. Everything the loop reads
// is copied into locals first, so the compiler keeps it in registers whatever `plot` writes. This
// is also the reference that the AVX2 kernel must match bit for bit.
//
// With kKeys, every lane also keeps the address key of its point (ifs/detail/address_raster.h:
// each step shifts the key right by `key_bits` and puts the map drawn in the top bits, burn-in
// included) and the call is plot(lane, pixel, map, key).
//
// With kPalette, every lane also keeps the palette coordinate of its point (DESIGN.md §4),
// c_k = (c_{k-1} + c_σk) / 2 in 16-bit fixed point with `palette[n]` = c_n, from 0 at the start
// of the chunk and at every step, burn-in and points off the raster included: like the position,
// it is the walker's state, so it depends on the lane's own draws only, never on the chunks a
// worker ran before. The call is plot(lane, pixel, map, c).
template <bool kKeys, bool kPalette = false, class Plot>
void walk_chunk_scalar(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                       std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                       int key_bits, const std::uint32_t* palette, Plot&& plot) {
  static_assert(!(kKeys && kPalette), "a walk keeps keys or palette coordinates, not both");
  const MapPicker::View pick = picker.view();
  const double *a = maps.a.data(), *b = maps.b.data(), *c = maps.c.data();
  const double *d = maps.d.data(), *e = maps.e.data(), *f = maps.f.data();
  const double sx = mapping.sx, ox = mapping.ox, sy = mapping.sy, oy = mapping.oy;
  const double width = mapping.width, height = mapping.height;
  const long stride = mapping.stride;
  const int key_shift = 64 - key_bits;
  LaneRng rng[kLanes];
  double x[kLanes], y[kLanes];
  std::uint64_t key[kLanes] = {};
  std::uint32_t colour[kLanes] = {};
  for (int lane = 0; lane < kLanes; ++lane) {
    rng[lane].seed(seed, chunk, lane);
    x[lane] = start_coordinate(rng[lane]);
    y[lane] = start_coordinate(rng[lane]);
  }
  auto step = [&](int lane) {
    const std::uint32_t n = pick(rng[lane].next());
    const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
    const double ny = c[n] * x[lane] + d[n] * y[lane] + f[n];
    x[lane] = nx;
    y[lane] = ny;
    if constexpr (kKeys) key[lane] = (key[lane] >> key_bits) | (std::uint64_t{n} << key_shift);
    if constexpr (kPalette) colour[lane] = (colour[lane] + palette[n]) >> 1;
    return n;
  };
  for (int k = 0; k < burn_in; ++k)
    for (int lane = 0; lane < kLanes; ++lane) step(lane);
  auto advance = [&](int lane) {
    const std::uint32_t n = step(lane);
    const double px = sx * x[lane] + ox, py = sy * y[lane] + oy;
    // Non-short-circuit tests: one well-predicted branch instead of four.
    if ((px >= 0) & (px < width) & (py >= 0) & (py < height)) {
      const long pixel = static_cast<long>(py) * stride + static_cast<long>(px);
      if constexpr (kKeys) {
        plot(lane, pixel, n, key[lane]);
      } else if constexpr (kPalette) {
        plot(lane, pixel, n, colour[lane]);
      } else {
        plot(lane, pixel, n);
      }
    }
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t k = 0; k < steps; ++k) {
#pragma GCC unroll 8
    for (int lane = 0; lane < kLanes; ++lane) advance(lane);
  }
  for (int lane = 0; lane < static_cast<int>(points % kLanes); ++lane) advance(lane);
}

template <class Plot>
void plot_chunk_scalar(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                       std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                       Plot&& plot) {
  walk_chunk_scalar<false>(maps, picker, mapping, seed, chunk, points, burn_in, 0, nullptr, plot);
}

}  // namespace ifsfx::detail

#include "ifs/detail/walkers_avx2.h"

namespace ifsfx::detail {

// The walkers of one chunk on the AVX2 loop where the CPU and the IFS allow it, else on the scalar
// one; both give the same points (and keys, with kKeys).
template <bool kKeys, bool kPalette = false, class Plot>
void walk_chunk(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                int key_bits, const std::uint32_t* palette, Plot&& plot) {
#ifdef __AVX2__
  if (maps.a.size() <= kAvx2MaxMaps) {
    walk_chunk_avx2<kKeys, kPalette>(maps, picker, mapping, seed, chunk, points, burn_in, key_bits,
                                     palette, plot);
    return;
  }
#endif
  walk_chunk_scalar<kKeys, kPalette>(maps, picker, mapping, seed, chunk, points, burn_in, key_bits,
                                     palette, plot);
}

// The renderers' entry: plot(lane, pixel, map) for every point that lands on the raster.
template <class Plot>
void plot_chunk(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                Plot&& plot) {
  walk_chunk<false>(maps, picker, mapping, seed, chunk, points, burn_in, 0, nullptr, plot);
}

// plot_chunk with the palette coordinates of the walkers (DESIGN.md §4, see walk_chunk_scalar):
// plot(lane, pixel, map, c), c in 16-bit fixed point, `palette[n]` = c_n of map n.
template <class Plot>
void plot_chunk_coloured(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                         std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                         const std::uint32_t* palette, Plot&& plot) {
  walk_chunk<false, true>(maps, picker, mapping, seed, chunk, points, burn_in, 0, palette, plot);
}

// plot_chunk with the address keys of the walkers: plot(lane, pixel, map, key), keys shifted by
// `key_bits` a step (see walk_chunk_scalar).
template <class Plot>
void plot_chunk_keyed(const MapTable& maps, const MapPicker& picker, const PixelMapping& mapping,
                      std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, int burn_in,
                      int key_bits, Plot&& plot) {
  walk_chunk<true>(maps, picker, mapping, seed, chunk, points, burn_in, key_bits, nullptr, plot);
}

}  // namespace ifsfx::detail
