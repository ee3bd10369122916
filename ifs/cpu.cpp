#include "ifs/cpu.h"

#include <cctype>
#include <cstdlib>
#include <string>

#include "ifs/detail/cpu_level.h"
#include "ifs/error.h"

namespace ifsfx {

const char* to_string(CpuLevel level) noexcept {
  switch (level) {
    case CpuLevel::scalar:
      return "scalar";
    case CpuLevel::avx2:
      return "avx2";
    case CpuLevel::avx512:
      return "avx512";
  }
  return "scalar";
}

std::vector<CpuLevel> supported_cpu_levels() {
  std::vector<CpuLevel> levels{CpuLevel::scalar};
#if IFSFX_X86_KERNELS
  // libgcc reads CPUID and checks that the OS saves the YMM and ZMM registers (XGETBV). The AVX2
  // kernels are compiled for x86-64-v3 (less FMA), the AVX-512 ones for x86-64-v4 (less FMA).
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v3")) levels.push_back(CpuLevel::avx2);
  if (__builtin_cpu_supports("x86-64-v4")) levels.push_back(CpuLevel::avx512);
#endif
  return levels;
}

CpuLevel best_cpu_level() {
  return supported_cpu_levels().back();
}

namespace detail {

CpuLevel select_cpu_level(const char* request, const std::vector<CpuLevel>& supported) {
  if (request == nullptr || *request == '\0') return supported.back();
  std::string runs;
  for (CpuLevel level : supported) runs += std::string(runs.empty() ? "" : ", ") + to_string(level);
  std::string name(request);  // any case: IFSFX_CPU=AVX2 as OpenCV's variables spell levels
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (CpuLevel level : {CpuLevel::scalar, CpuLevel::avx2, CpuLevel::avx512}) {
    if (name != to_string(level)) continue;
    for (CpuLevel s : supported)
      if (s == level) return level;
    throw Error(ErrorKind::invalid_argument, "IFSFX_CPU: this CPU runs the kernel levels " + runs +
                                                 " only (got " + request + ")");
  }
  throw Error(ErrorKind::invalid_argument,
              "IFSFX_CPU: must name a kernel level, scalar, avx2 or avx512 (got '" +
                  std::string(request) + "')");
}

}  // namespace detail

CpuLevel cpu_level() {
  // Once: every kernel call of the program runs at one level. (The one getenv of the libraries:
  // see cpu.h for why.)
  static const CpuLevel level =
      detail::select_cpu_level(std::getenv("IFSFX_CPU"), supported_cpu_levels());
  return level;
}

}  // namespace ifsfx
