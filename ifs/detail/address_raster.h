// SPDX-License-Identifier: Apache-2.0
// Private to ifs/: per-pixel top addresses on a raster, the common ground of the tops renderer
// and of both ways of computing a steal map (docs/design.md §2–3).
//
// An address σ1 σ2 σ3 … (most recent map first) is packed into a 64-bit key, σ1 in the top b
// bits, b = ceil(log2 N): an unsigned compare of two keys is the lexicographic compare of their
// first 64/b symbols, which is the order of eq. 7 (Top keeps the larger address). Bit 0 of a
// stored key is forced to 1 so that 0 can mean "no point landed here"; it only touches the last
// symbol's lowest bit, 64/b symbols deep.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/detail/walkers.h"
#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/tops.h"
#include "ifs/view.h"

namespace ifsfx::detail {

// b = ceil(log2 N), at least 1.
int symbol_bits(std::size_t n);

struct AddressRaster {
  Viewport viewport;
  int bits = 1;                     // b
  int key_bits = 64;                // bits of each key that hold symbols (from the top)
  std::vector<std::uint64_t> keys;  // row-major, 0 = not on the attractor

  int symbols() const { return key_bits / bits; }
  std::uint64_t at(int col, int row) const {
    return keys[static_cast<std::size_t>(row) * viewport.size.width + col];
  }
  // Symbol k (0 = σ1, the first map of the address) of a key.
  std::uint32_t symbol(std::uint64_t key, int k) const {
    return static_cast<std::uint32_t>((key >> (64 - bits * (k + 1))) & ((1u << bits) - 1));
  }
  cv::Mat coverage() const;  // CV_8UC1, 255 where a key is stored
};

// The chaos-game coverage policy: `quality` points per pixel, then further rounds of quality/4
// per pixel while a round still adds more than 0.1 % to the pixels hit (at most kMaxGrowthRounds),
// then Hutchinson passes (one more step from every pixel's point, by every map, into pixels
// no point reached; up to 4 passes), then holes are filled from neighbours: a pixel no point
// reached but with hit neighbours on both sides along a row, a column or a diagonal (at a corner
// of the raster: all three neighbours hit) lies inside the attractor's raster, and takes the
// largest key among its hit 8-neighbours (the tops rule applied to the neighbourhood).
struct ChaosTopsOptions {
  double quality = 64;
  std::uint64_t seed = 1;
  int threads = 0;
  bool grow = true;  // the growth rounds
  bool fill = true;  // the Hutchinson passes and the hole filling
  // Bits kept per pixel record: 32 halves the buffer (faster), and holds 32/b symbols, enough
  // for tops and masks and for colouring IFSs that contract fast enough (see steal_map.cpp).
  int key_bits = 64;
  CancelToken cancel;  // polled per chunk of points and per pass
};

inline constexpr int kMaxGrowthRounds = 8;

struct ChaosTopsStats {
  std::uint64_t points = 0;    // points plotted (burn-in excluded)
  std::size_t hit = 0;         // pixels some point reached
  std::size_t propagated = 0;  // pixels reached by the Hutchinson passes
  std::size_t filled = 0;      // pixels filled from neighbours
  int rounds = 0;              // rounds run, the first included
};

// Fractal tops by the chaos game (docs/design.md §2): every pixel keeps the largest key of the
// points that landed in it. Deterministic for a seed, whatever the thread count.
AddressRaster chaos_tops(const Ifs& F, const Viewport& viewport, const ChaosTopsOptions& options,
                         ChaosTopsStats* stats = nullptr);

// A chaos game that plots address keys: F's affine walkers above, or a flame's xforms
// (flame/flame_chaos.h). run32/run64 plot `points` points of chunk `chunk` of the walk seeded
// with `seed` into one worker's records (row-major on the viewport), each record keeping the
// largest key cut to its top 32 or 64 bits, bit 0 set (what walk_kernels.h's tops sinks do). The
// result must depend on (seed, chunk, points) only.
struct KeyWalk {
  std::function<void(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     std::uint32_t* cells)>
      run32;
  std::function<void(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     std::uint64_t* cells)>
      run64;
  int bits = 1;                               // b = ceil(log2 N)
  std::uint64_t chunk_points = kChunkPoints;  // points a chunk of the walk plots (walkers.h)
  // The Hutchinson passes step every pixel's point by these maps, in the viewport's plane: the
  // walk's own maps when they are affine and contract; none skips the passes (a flame's xforms
  // have no contraction bound that would keep a rebuilt point on the attractor).
  const Ifs* affine = nullptr;
};

// The coverage policy above over any walk of address keys.
AddressRaster chaos_tops(const KeyWalk& walk, const Viewport& viewport,
                         const ChaosTopsOptions& options, ChaosTopsStats* stats = nullptr);

// The exact top-address descent (docs/design.md §3) from every pixel centre of `viewport`.
struct DescentOptions {
  int levels = 2;  // L: symbols followed per pixel
  // Points per mask pixel for the attractor mask before the growth rounds (which add what a low
  // density misses: 4 gives the fern 99.9 % of the pixels 16 gives, at a third of the cost).
  double quality = 4;
  std::uint64_t seed = 1;
  int threads = 0;
  CancelToken cancel;  // polled per band of pixels (and by the attractor mask's chaos game)
};

struct Descent {
  AddressRaster tops;  // the first min(L, 64/b) symbols of each covered pixel
  cv::Mat uv;          // CV_32FC2 T(x) as normalised image coordinates, when G was given
};

// Follows the top address of each pixel centre through a conservative attractor mask. With a
// colouring IFS G (same N), also evaluates T(x) = g_σ1 ∘ … ∘ g_σL(c) into `uv`.
Descent exact_descent(const Ifs& F, const Ifs* G, const Viewport& viewport,
                      const DescentOptions& options, ChaosTopsStats* mask_stats = nullptr);

// Contraction of G over words: min over k = 1..3 of (max over words w of length k of ‖g_w‖)^(1/k),
// which is < 1 for the swap tilings whose single maps have factor 1.
double word_contraction(const Ifs& G);

// Levels L such that s^L ≤ 2^-20: T is then within a millionth of the unit square.
int levels_for(double contraction);

// The first two symbols of every covered pixel of `tops` (TopSymbols::points left 0).
TopSymbols symbols_of(const AddressRaster& tops);

// Evaluates T from keys for the chaos-game steal map: T ≈ g_σ1 ∘ … ∘ g_σm(c), m the symbols
// after which F's piece holding the pixel's point has shrunk to a pixel, c the centre of G's
// attractor. CV_32FC2 (u, v), v = 1 − y; uncovered pixels get (0, 0).
cv::Mat uv_from_keys(const AddressRaster& tops, const Ifs& F, const Ifs& G, int threads);

// Fixed point of an affine map, or the centre of the unit square when it has none.
Point fixed_point(const AffineMap& g);

}  // namespace ifsfx::detail
