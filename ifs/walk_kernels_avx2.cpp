// SPDX-License-Identifier: Apache-2.0
// The chaos-game kernels on AVX2 (compiled with -march=x86-64-v3 -mno-fma, see ifs/CMakeLists.txt;
// chosen at run time, ifs/cpu.h): the eight lanes of a chunk as two vectors of four doubles
// (walk_quads.inl) for IFSs of up to 8 maps; larger ones run walk_scalar, compiled here for this
// instruction set. Every mode gives the bytes of the scalar level.
#include <immintrin.h>

#include "ifs/detail/walk_kernels.h"

namespace ifsfx::detail::kernel_avx2 {
namespace {

#include "ifs/detail/walk_kernels_common.inl"

constexpr CpuLevel kLevel = CpuLevel::avx2;

#include "ifs/detail/walk_quads.inl"

template <class Sink, bool kWrap>
void walk(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  if (w.maps <= 4)
    walk_quads<Sink, false, kWrap>(w, seeds, points, sink);
  else if (w.maps <= 8)
    walk_quads<Sink, true, kWrap>(w, seeds, points, sink);
  else
    walk_scalar<Sink, kWrap>(w, seeds, points, sink);
}

template <class Sink>
void walk(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  if (w.wrap)
    walk<Sink, true>(w, seeds, points, sink);
  else
    walk<Sink, false>(w, seeds, points, sink);
}

#include "ifs/detail/walk_kernels_table.inl"

}  // namespace

constexpr WalkKernels table = kernels;

}  // namespace ifsfx::detail::kernel_avx2
