// SPDX-License-Identifier: Apache-2.0
// The attractor loss's chaos game (collage/attractor_loss.h), one kernel per level (ifs/cpu.h):
// the scalar reference in collage/play_kernel.cpp and AVX2 in collage/play_kernel_avx2.cpp
// (AVX-512 runs the AVX2 one), each in its level's namespace, equal bit for bit.
//
// Eight chains side by side in float (a point of the plane needs far fewer than float's 24 bits
// at 512²: a pixel is 2⁻⁹ of the square), each on its own run of the common random numbers. A
// step of lane l at time t:
//   u = draws[8 t + l];  n = #{k < N − 1 : u ≥ cumulative[k]}     (probabilities ∝ |det|)
//   x' = (a_n x + b_n y) + e_n,  y' = (c_n x + d_n y) + f_n        (mul then add, no FMA)
// and after the burn-in its pixel point p = (x' s + pad, (1 − y') s + pad) on the canvas adds
// the distance map's bilinear value at p to the lane's spill (in double) and marks its pixel
// hit. The bilinear value, between pixel centres (u = p − ½ clamped to [0, side − 1], the cell
// c₀ = min(⌊u⌋, side − 2), the fraction u − c₀):
//   top = d₀₀ + f_u (d₀₁ − d₀₀),  bottom = d₁₀ + f_u (d₁₁ − d₁₀),
//   value = (top + f_v (bottom − top)) + √(Δu² + Δv²)
// where Δ is the way from p − ½ to its clamped point (0 inside: an upper bound outside). The
// maps are picked by compares, never by a branch: the draws pick at random.
//
// Plain data only crosses into a kernel (no default member initialisers, nothing inline shared
// with baseline code: ifs/detail/walk_kernels.h says why, tests/ifs/kernel_isolation_test.sh
// checks the binary).
#pragma once

#include <cstddef>
#include <cstdint>

#include "ifs/cpu.h"

namespace ifsfx::collage::detail {

inline constexpr std::size_t kPlayLanes = 8;

struct PlayInput {
  const float* draws;  // steps × kPlayLanes, step-major: draws[8 t + lane], uniform in [0, 1)
  std::size_t steps;
  std::size_t burn_in;  // the first steps of each lane, not counted
  // The maps as six rows (a, b, c, d, e, f) of `stride` floats: map n's a is coefficients[n],
  // its f coefficients[5 stride + n]. stride ≥ max(N, 8), the rest zero.
  const float* coefficients;
  int stride;
  int count;                // N ≥ 1
  const float* cumulative;  // N − 1 thresholds: the first k + 1 maps' summed probabilities
  // The distance d to L's nearest pixel centre on the side × side canvas, by cells: cell (r, c)
  // at 4 (r side + c) holds its corners d₀₀ = d(r, c), d₀₁ = d(r, c + 1), d₁₀ = d(r + 1, c),
  // d₁₁ = d(r + 1, c + 1), for r, c ≤ side − 2: the look-up's one load.
  const float* cells;
  int side;         // the canvas, ≥ 2
  float size, pad;  // the plane's unit square is pixels [pad, pad + size)²
  // side × side + 1 bytes, or null: 1 where a counted point lands on the canvas; the last byte
  // is a sink that a kernel may mark for points off it.
  std::uint8_t* hits;
};

// The summed spill of every counted point, in pixels: the lanes' sums added in lane order.
using PlayFunction = double (*)(const PlayInput&);

// The kernel of `level` (scalar below AVX2, AVX2 at AVX2 and above).
PlayFunction play_function(CpuLevel level);

}  // namespace ifsfx::collage::detail

namespace ifsfx::detail::kernel_scalar {
double collage_play(const collage::detail::PlayInput& in);
}
namespace ifsfx::detail::kernel_avx2 {
double collage_play(const collage::detail::PlayInput& in);
}
