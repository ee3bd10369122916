// SPDX-License-Identifier: Apache-2.0
// The chaos-game kernels of the renderers, one table of them per kernel level (ifs/cpu.h): the
// whole chunk loop of every mode — the walkers and what they plot — compiled once per instruction
// set, in ifs/walk_kernels_<level>.cpp, each in a namespace of its own (kernel_scalar,
// kernel_avx2, kernel_avx512).
//
// What crosses from the baseline code into a kernel is plain data, declared here: structs without
// member functions, raw pointers, constants. Nothing of the kernels is shared with the baseline
// code — no inline function, no template instance — because the linker keeps one copy of each
// (COMDAT folding) and could otherwise keep the AVX2 one and call it from baseline code, an illegal
// instruction on a CPU without AVX2. tests/ifs/kernel_isolation_test.cmake checks the binary.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ifs/cpu.h"

namespace ifsfx::detail {

// Walkers iterated in lockstep inside a chunk: independent dependency chains the CPU overlaps,
// and the lanes of the vector kernels (2×4 for AVX2, 8 for AVX-512).
inline constexpr int kLanes = 8;

// Everything a chunk's walkers read. Maps as structure of arrays (x' = a x + b y + e,
// y' = c x + d y + f), the alias tables of MapPicker, and the plane → pixel mapping
// px = sx·x + ox, py = sy·y + oy (pixel (c, r) covers [c, c+1) × [r, r+1)).
// (No default member initialisers in these structs: they stay trivial, so a kernel never needs
// a constructor.)
struct WalkSpec {
  std::uint32_t maps;  // N
  const double *a, *b, *c, *d, *e, *f;
  std::uint64_t pick_n;  // MapPicker::View
  const std::uint32_t* threshold;
  const std::uint32_t* alias;
  double sx, ox, sy, oy;
  double width, height;          // of the raster
  long stride;                   // pixels per row
  int burn_in;                   // steps of each lane before it plots
  int key_bits;                  // b: bits per symbol of the address keys (tops)
  const std::uint32_t* palette;  // c_n of each map, 16-bit fixed point (palette coordinates)
  // 1: the walk is on the torus of the tile (docs/design.md §11): coordinates are the tile's,
  // [0,1)² with v down, and every step ends with the wrap t − ⌊t⌋ of both (0 for the 1 that
  // rounding gives a tiny negative t); 0: the plane, no wrap.
  int wrap;
};

// The xoshiro256+ state of each lane at the start of a chunk (lane_seeds() in walkers.h).
struct LaneSeeds {
  std::uint64_t s[kLanes][4];
};

// render_measure's accumulation: per raster cell one 32-bit word, the visit count in its low
// kCountBits bits and Σc6 above them (c6: the palette coordinate quantised to kPaletteBits) —
// half the bytes of a 64-bit count and sum, so a 1080p raster is 8 MiB and two workers' rasters
// stay in the shared cache. A cell whose count reaches kFull spills: (Σc6 << 32 | cell) is
// appended to `spills` (its count, kFull, implied) and the cell starts again from 0, so a stored
// count is always below kFull. Each spill takes kFull points, so from empty cells (and no spills)
// `points` points need room for points / kFull spills. fold_measure_cells adds both to totals.
struct MeasureCells {
  static constexpr int kPaletteBits = 6;
  static constexpr int kCountBits = 13;  // Σc6 of kFull points < 2^(kCountBits + kPaletteBits)
  static constexpr std::uint32_t kFull = (1u << kCountBits) - 1;
  static_assert(2 * kCountBits + kPaletteBits <= 32);

  std::uint32_t* cells;
  std::uint64_t* spills;
  std::uint64_t spilled;  // entries of `spills` in use
};

// One plotted point, as the walkers see it (for the tests and the kernel check program).
struct TracedPoint {
  std::int32_t lane;
  std::uint32_t map;      // σk
  std::int64_t pixel;     // row · stride + column
  std::uint64_t key;      // address key: σk in the top key_bits bits, then σk-1, ...
  std::uint32_t palette;  // c_k, 16-bit fixed point
  std::uint32_t zero;     // 0: no padding, so that traces compare with memcmp
  double x, y;            // the point in the plane: any rounding difference shows here
};

// The kernels of one level. Each runs `points` chaos-game points of one chunk (8 lanes from
// `seeds`, each with its burn-in; points interleaved lane by lane) and plots those that land on
// the raster:
struct WalkKernels {
  CpuLevel level;
  // hits[pixel] = 255 (the attractor as a set)
  void (*hits)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, std::uint8_t* hits);
  // ++counts[pixel] (visit counts)
  void (*counts)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, std::uint32_t* counts);
  // the point and its palette coordinate into `cells` (see MeasureCells)
  void (*measure)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, MeasureCells& cells);
  // cells[pixel] = max(cells[pixel], key >> (64 − cell bits) | 1) (fractal tops, eq. 7)
  void (*tops32)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, std::uint32_t* cells);
  void (*tops64)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, std::uint64_t* cells);
  // every plotted point in order into `out` (room for `points` entries); returns how many
  std::size_t (*trace)(const WalkSpec&, const LaneSeeds&, std::uint64_t points, TracedPoint* out);
};

// The lanes of chunk `chunk` of the run seeded with `seed`: lane l's xoshiro256+ state from
// stream_seed(seed, chunk · kLanes + l), expanded by SplitMix64.
LaneSeeds lane_seeds(std::uint64_t seed, std::uint64_t chunk);

// Adds the `area` cells and the spills of `m` to the totals (count[i] visits, colour[i] Σc6 of
// cell i) and empties both.
void fold_measure_cells(MeasureCells& m, std::size_t area, std::uint64_t* count,
                        std::uint64_t* colour);

// The kernels of `level`. Throws Error{unsupported} for a level this CPU or build does not run.
const WalkKernels& walk_kernels(CpuLevel level);
// The kernels of cpu_level().
const WalkKernels& walk_kernels();

// The tables themselves, one per translation unit (walk_kernels_<level>.cpp).
namespace kernel_scalar {
extern const WalkKernels table;
}
namespace kernel_avx2 {
extern const WalkKernels table;
}
namespace kernel_avx512 {
extern const WalkKernels table;
}

}  // namespace ifsfx::detail
