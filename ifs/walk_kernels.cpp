// SPDX-License-Identifier: Apache-2.0
// The dispatcher of the chaos-game kernels: the table of the level asked for, or of cpu_level().
#include "ifs/detail/walk_kernels.h"

#include <string>

#include "ifs/error.h"
#include "ifs/rng.h"

namespace ifsfx::detail {

LaneSeeds lane_seeds(std::uint64_t seed, std::uint64_t chunk) {
  LaneSeeds out;
  for (int lane = 0; lane < kLanes; ++lane) {
    std::uint64_t z = stream_seed(seed, chunk * kLanes + static_cast<std::uint64_t>(lane));
    for (auto& word : out.s[lane]) word = z = mix64(z + 0x9e3779b97f4a7c15ULL);
  }
  return out;
}

void fold_measure_cells(MeasureCells& m, std::size_t area, std::uint64_t* count,
                        std::uint64_t* colour) {
  for (std::uint64_t k = 0; k < m.spilled; ++k) {
    const std::uint64_t spill = m.spills[k];
    count[spill & 0xffffffffu] += MeasureCells::kFull;
    colour[spill & 0xffffffffu] += spill >> 32;
  }
  m.spilled = 0;
  for (std::size_t i = 0; i < area; ++i) {
    const std::uint32_t cell = m.cells[i];
    if (cell == 0) continue;
    count[i] += cell & MeasureCells::kFull;
    colour[i] += cell >> MeasureCells::kCountBits;
    m.cells[i] = 0;
  }
}

const WalkKernels& walk_kernels(CpuLevel level) {
  for (CpuLevel supported : supported_cpu_levels()) {
    if (supported != level) continue;
    switch (level) {
      case CpuLevel::scalar:
        return kernel_scalar::table;
#if IFSFX_X86_KERNELS
      case CpuLevel::avx2:
        return kernel_avx2::table;
      case CpuLevel::avx512:
        return kernel_avx512::table;
#endif
      default:
        break;
    }
  }
  throw Error(ErrorKind::unsupported,
              std::string("kernel level: this CPU or build does not run ") + to_string(level));
}

const WalkKernels& walk_kernels() {
  return walk_kernels(cpu_level());
}

}  // namespace ifsfx::detail
