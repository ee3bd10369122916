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
