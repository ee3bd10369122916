// SPDX-License-Identifier: Apache-2.0
// The variations over batches of points: the chaos game walks 256 walkers in lockstep
// (flame/render_chaos.cpp), and every walker that picked the same xform goes through its terms
// together, so a variation runs over an array of points, four at a time on AVX2. The registry's
// function (flame/variations.h) stays the definition; a batch form is the same formula written
// once (flame/detail/batch_kernels.inl) over a lane type and its own branch-free sin, cos,
// atan2, exp and log (flame/detail/vmath.inl), compiled for each kernel level (ifs/cpu.h) with
// the same operations in the same order and no fused multiply-add: every level gives the
// scalar level's bits. A variation with no batch form runs point by point through the registry.
//
//   const BatchVariation* b = find_batch_variation(cpu_level(), "spherical");
//   b->function({.w = 0.5, .params = p, .pre = &xf.pre}, n, x, y, sum_x, sum_y);
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "ifs/affine_map.h"
#include "ifs/cpu.h"

namespace ifsfx::flame::detail {

// Walkers of one chunk: 128 rather than 64 put more points in each xform's group of a step (5-8 %
// less CPU on variation-heavy genomes in double lanes), 256 rather than 128 another 2-6 % with
// eight float lanes; a 256-pixel quality-50 render is 2 chunks, its wall time on two threads
// the same as with 3 (one worker had two of them).
inline constexpr std::size_t kBatchLanes = 256;
inline constexpr std::size_t kBatchStride = kBatchLanes + 8;  // an array's length, padded

struct BatchTerm {
  double w = 1;
  const double* params = nullptr;  // the term's parameters, registry order
  const AffineMap* pre = nullptr;  // the xform's pre-affine map (dependent variations)
  // The random variations' draws, uniform in [0, 1): draw j of point i at u[j·kBatchStride + i].
  const double* u = nullptr;
};

// Adds w·V(x[i], y[i]) to (ox[i], oy[i]) for i < n; may also write entries up to n rounded up
// to the lane width (the arrays are kBatchStride long).
using BatchFunction = void (*)(const BatchTerm& t, std::size_t n, const double* x, const double* y,
                               double* ox, double* oy);

// The same over float arrays, the sums in float: a float form's points rounded once for all the
// terms of an xform's sum (flame/xform_step.cpp), not once a term.
using BatchFunctionF = void (*)(const BatchTerm& t, std::size_t n, const float* x, const float* y,
                                float* ox, float* oy);

struct BatchVariation {
  std::string_view name;  // the registry's name
  BatchFunction function = nullptr;
  BatchFunctionF function_f = nullptr;  // float lanes only
  int draws = 0;                        // uniforms per point
};

// The arithmetic of a batch form's lanes: doubles (four a register on AVX2) or floats (eight;
// shorter polynomials, flame/detail/vmath_f32.inl). Both take and give doubles: a float form
// rounds its points to float, evaluates in float and adds its result to the double sums.
enum class LaneType { f64, f32 };

// The batch forms of `level` (or of the scalar level where this build has no other).
std::span<const BatchVariation> batch_variations(CpuLevel level, LaneType type = LaneType::f64);

// The batch form of the variation called `name` at `level`, or nullptr.
const BatchVariation* find_batch_variation(CpuLevel level, std::string_view name,
                                           LaneType type = LaneType::f64);

// The supersampled raster as the walk's last step sees it: the camera's map to bin coordinates
// (flame/render_camera.h) and the bins across and down.
struct BinGrid {
  AffineMap to_bins;
  std::uint32_t bins_x = 0, bins_y = 0;
};
inline constexpr std::uint32_t kOffBin = UINT32_MAX;  // a point that is not plotted
inline constexpr double kEscape = 1e10;  // a point beyond this (or not a number) is re-seeded

// at[i] ← the bin number ⌊bx⌋ + bins_x·⌊by⌋ of point i, (bx, by) = to_bins(x[i], y[i]) as
// AffineMap computes it, for i < n; kOffBin where (bx, by) is outside [0, bins_x)×[0, bins_y)
// or the point has escaped (|x| or |y| not below kEscape, or not a number). Returns the number
// of escaped points. Reads up to n rounded up to 4 entries of x and y and writes as many of at.
// Branch-free over four double lanes on AVX2: a step's off-raster points mispredicted the
// scalar loop's branches (a quarter of a linear flame's time, perf at 27 Nov 12:00).
using BinFunction = std::size_t (*)(const BinGrid& g, std::size_t n, const double* x,
                                    const double* y, std::uint32_t* at);

// The bin numbering of `level` (the scalar one where this build has no other): every level
// gives the scalar level's numbers.
BinFunction bin_function(CpuLevel level);

// What a hit adds: each xform's 256 palette entries × its opacity as four 32-bit channels
// (r, g, b, a, in 1/65536 of a full hit, at most 2¹⁶ each), colours[k] + 4·entry; a linear
// palette mixes two neighbouring entries.
struct PlotTables {
  const std::uint32_t* const* colours = nullptr;
  bool linear = false;
  // When every xform sets the colour coordinate to its own (colour_speed 1, as Fractorium's
  // tilings have), a hit's colour is its xform's: fixed + 4·k, looked up without mixing.
  const std::uint32_t* fixed = nullptr;
};

// Plots the walkers hits[j] for j in [from, n), whose bins are not kOffBin (HitsFunction; the
// walkers j themselves where hits is null, all with bins): for walker i = hits[j], the colour of
// coordinate c[i] in xform k[i]'s table added to the four 32-bit sums of bin at[i] (bins +
// 4·at[i]). Stops after a hit that wraps a sum past 2³², returning j + 1 and the wrapped channels
// as bits 0-3 of *wrapped (the caller logs their carries and goes on from there); returns n when
// none wrapped. Integer sums: every level gives the scalar level's, with the 32-bit multiplies of a
// linear palette's mix in one instruction on AVX2 (baseline SSE2 has none).
using PlotFunction = std::size_t (*)(const PlotTables& t, std::uint32_t* bins, std::size_t from,
                                     std::size_t n, const std::uint32_t* hits,
                                     const std::uint32_t* at, const std::uint32_t* k,
                                     const double* c, unsigned* wrapped);

PlotFunction plot_function(CpuLevel level);

// The walkers listed by the xform each picked: order[first[j], first[j + 1]) holds the walkers
// i < m with k[i] = j, in ascending order, for j < steps ≤ kListXforms. Reads k up to m rounded
// up to 8, writes up to m + 8 entries of order and steps + 1 of first. On AVX2 eight walkers at
// a time for each xform (compare, mask, a table's permutation): the counting sort it replaces
// waited on its counters in memory (a third of the walk's own time, perf at 27 Nov 17:30).
inline constexpr std::size_t kListXforms = 8;
using ListFunction = void (*)(const std::uint32_t* k, std::size_t m, std::size_t steps,
                              std::uint32_t* order, std::size_t* first);

ListFunction list_function(CpuLevel level);

// The walkers to plot: hits ← the i < m whose at[i] is not kOffBin, in ascending order; returns
// their count. Reads at up to m rounded up to 8, writes up to m + 8 entries of hits. Branch-free
// (eight at a time on AVX2, as the listing by xform): the plot's own test of each walker was a
// branch mispredicted wherever points fall off the raster or on invisible xforms at random (half
// of a step's walkers in genome 4, perf at 27 Nov 20:00).
using HitsFunction = std::size_t (*)(const std::uint32_t* at, std::size_t m, std::uint32_t* hits);

HitsFunction hits_function(CpuLevel level);

}  // namespace ifsfx::flame::detail

// Each level's table (flame/batch_scalar.cpp, flame/batch_avx2.cpp), in the kernel namespaces
// that alone may hold instructions beyond baseline x86-64 (tests/ifs/kernel_isolation_test.sh).
namespace ifsfx::detail::kernel_scalar {
std::span<const flame::detail::BatchVariation> flame_batch_table();
void flame_list_by_xform(const std::uint32_t* k, std::size_t m, std::size_t steps,
                         std::uint32_t* order, std::size_t* first);
std::span<const flame::detail::BatchVariation> flame_batch_table_f32();
std::size_t flame_bin_numbers(const flame::detail::BinGrid& g, std::size_t n, const double* x,
                              const double* y, std::uint32_t* at);
std::size_t flame_plot(const flame::detail::PlotTables& t, std::uint32_t* bins, std::size_t from,
                       std::size_t n, const std::uint32_t* hits, const std::uint32_t* at,
                       const std::uint32_t* k, const double* c, unsigned* wrapped);
std::size_t flame_hits(const std::uint32_t* at, std::size_t m, std::uint32_t* hits);
}  // namespace ifsfx::detail::kernel_scalar
namespace ifsfx::detail::kernel_avx2 {
std::span<const flame::detail::BatchVariation> flame_batch_table();
void flame_list_by_xform(const std::uint32_t* k, std::size_t m, std::size_t steps,
                         std::uint32_t* order, std::size_t* first);
std::span<const flame::detail::BatchVariation> flame_batch_table_f32();
std::size_t flame_bin_numbers(const flame::detail::BinGrid& g, std::size_t n, const double* x,
                              const double* y, std::uint32_t* at);
std::size_t flame_plot(const flame::detail::PlotTables& t, std::uint32_t* bins, std::size_t from,
                       std::size_t n, const std::uint32_t* hits, const std::uint32_t* at,
                       const std::uint32_t* k, const double* c, unsigned* wrapped);
std::size_t flame_hits(const std::uint32_t* at, std::size_t m, std::uint32_t* hits);
}  // namespace ifsfx::detail::kernel_avx2
