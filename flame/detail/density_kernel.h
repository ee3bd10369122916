// SPDX-License-Identifier: Apache-2.0
// Density estimation's inner loop (flame/render_tone.cpp): one row of a bin's disc added to the
// picture, o[4i + k] += w[i]·v[k] for i < n and the four channels k, a product then a sum (no
// fused multiply-add), so that every kernel level (ifs/cpu.h) gives the scalar level's bits.
// Two doubles a register at the scalar level (SSE2), four on AVX2, where the row was 15–20 %
// faster per tap on the Zen 1 measured (bench figures in docs/flames.md, "Speed").
//   const SpreadRowFunction spread_row = spread_row_function(cpu_level());
//   spread_row(picture.at(y, x0), weights, n, v);
#pragma once

#include "ifs/cpu.h"

namespace ifsfx::flame::detail {

using SpreadRowFunction = void (*)(double* o, const double* w, int n, const double* v);

SpreadRowFunction spread_row_function(CpuLevel level);

}  // namespace ifsfx::flame::detail

// Each level's loop (flame/render_tone.cpp, flame/density_avx2.cpp), in the kernel namespaces
// that alone may hold instructions beyond baseline x86-64 (tests/ifs/kernel_isolation_test.sh).
namespace ifsfx::detail::kernel_scalar {
void flame_spread_row(double* o, const double* w, int n, const double* v);
}  // namespace ifsfx::detail::kernel_scalar
namespace ifsfx::detail::kernel_avx2 {
void flame_spread_row(double* o, const double* w, int n, const double* v);
}  // namespace ifsfx::detail::kernel_avx2
