// SPDX-License-Identifier: Apache-2.0
// The chaos-game kernels at the scalar level: walk_scalar, the reference every other level must
// match byte for byte, compiled for baseline x86-64 (or whatever processor this is built for).
#include "ifs/detail/walk_kernels.h"

namespace ifsfx::detail::kernel_scalar {
namespace {

#include "ifs/detail/walk_kernels_common.inl"

constexpr CpuLevel kLevel = CpuLevel::scalar;

template <class Sink>
void walk(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  walk_scalar(w, seeds, points, sink);
}

#include "ifs/detail/walk_kernels_table.inl"

}  // namespace

constexpr WalkKernels table = kernels;

}  // namespace ifsfx::detail::kernel_scalar
