// SPDX-License-Identifier: Apache-2.0
// Kernel levels: the instruction sets the hot kernels of the libraries are compiled for. The
// libraries are built for baseline x86-64; each kernel also exists in translation units of its
// own compiled for AVX2 and AVX-512, and the level is chosen once, at run time, from what the CPU
// reports (docs/design.md §9). Every level gives the same bytes as the scalar one, which is the
// reference: same operations in the same order, no fused multiply-add.
//
// The environment variable IFSFX_CPU=scalar|avx2|avx512 forces a level (for tests, and for users
// chasing a bug). It is the one setting the libraries read from the environment, on purpose, as
// OpenCV reads OPENCV_CPU_DISABLE: a kernel level changes no result, only speed, and it must be
// settable for a program that was not written to pass it.
//   fmt::print("kernels: {}\n", to_string(cpu_level()));
#pragma once

#include <vector>

namespace ifsfx {

enum class CpuLevel {
  scalar,  // baseline x86-64 (SSE2), or any other processor
  avx2,    // AVX2 with BMI1/BMI2, LZCNT, MOVBE, F16C (x86-64-v3, without FMA): Haswell and later
  avx512,  // AVX-512 F/BW/CD/DQ/VL on top (x86-64-v4): Skylake-X, Ice Lake, Zen 4 and later
};

// "scalar", "avx2" or "avx512".
const char* to_string(CpuLevel level) noexcept;

// The levels this build has kernels for and this CPU runs, lowest first (scalar is always there).
std::vector<CpuLevel> supported_cpu_levels();

// The highest of supported_cpu_levels().
CpuLevel best_cpu_level();

// The level the kernels run at: the one IFSFX_CPU names, else best_cpu_level(). Read once, at the
// first call. Throws Error{invalid_argument} naming IFSFX_CPU when it names no level, or a level
// this CPU (or this build) does not run: a request above the CPU is refused, never run into an
// illegal instruction.
CpuLevel cpu_level();

}  // namespace ifsfx
