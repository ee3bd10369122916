// SPDX-License-Identifier: Apache-2.0
#include "ifs/cpu.h"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <string>

#if IFSFX_X86_KERNELS
#include <cpuid.h>
#endif

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

namespace {

#if IFSFX_X86_KERNELS

// CPUID read directly (<cpuid.h>, GCC and clang alike): __builtin_cpu_supports("x86-64-v3") is
// GCC's only, and neither compiler's builtin names every feature of the levels (LZCNT, MOVBE).
struct CpuidBits {
  unsigned leaf, subleaf;
  int reg;  // 0 eax, 1 ebx, 2 ecx, 3 edx
  int bit;
};

bool cpuid_has(const CpuidBits& f) {
  unsigned r[4] = {};
  if (static_cast<unsigned>(__get_cpuid_max(f.leaf & 0x80000000u, nullptr)) < f.leaf) return false;
  __cpuid_count(f.leaf, f.subleaf, r[0], r[1], r[2], r[3]);
  return (r[f.reg] >> f.bit) & 1u;
}

bool cpuid_has_all(std::initializer_list<CpuidBits> features) {
  for (const CpuidBits& f : features)
    if (!cpuid_has(f)) return false;
  return true;
}

// The register state the OS saves on a context switch (XCR0): without it the instructions fault.
std::uint64_t os_saved_state() {
  if (!cpuid_has({1, 0, 2, 27})) return 0;  // OSXSAVE: XGETBV usable
  unsigned lo = 0, hi = 0;
  __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
  return (static_cast<std::uint64_t>(hi) << 32) | lo;
}

#endif

// CPUID is slow (each one a VM exit under a hypervisor) and the answer never changes: read once.
std::vector<CpuLevel> probe_cpu_levels() {
  std::vector<CpuLevel> levels{CpuLevel::scalar};
#if IFSFX_X86_KERNELS
  // The AVX2 kernels are compiled for x86-64-v3, the AVX-512 ones for x86-64-v4 (never with
  // contracted multiply-adds: ifs/CMakeLists.txt): each level needs every feature of its psABI
  // level and the OS saving the YMM (XCR0 bits 1-2) and ZMM state (bits 5-7).
  const std::uint64_t state = os_saved_state();
  const bool v3 = (state & 0x6) == 0x6 && cpuid_has_all({{1, 0, 2, 12},             // FMA
                                                         {1, 0, 2, 22},             // MOVBE
                                                         {1, 0, 2, 28},             // AVX
                                                         {1, 0, 2, 29},             // F16C
                                                         {7, 0, 1, 3},              // BMI1
                                                         {7, 0, 1, 5},              // AVX2
                                                         {7, 0, 1, 8},              // BMI2
                                                         {0x80000001u, 0, 2, 5}});  // LZCNT
  if (v3) levels.push_back(CpuLevel::avx2);
  const bool v4 = v3 && (state & 0xe6) == 0xe6 &&
                  cpuid_has_all({{7, 0, 1, 16},    // AVX512F
                                 {7, 0, 1, 17},    // AVX512DQ
                                 {7, 0, 1, 28},    // AVX512CD
                                 {7, 0, 1, 30},    // AVX512BW
                                 {7, 0, 1, 31}});  // AVX512VL
  if (v4) levels.push_back(CpuLevel::avx512);
#endif
  return levels;
}

}  // namespace

std::vector<CpuLevel> supported_cpu_levels() {
  static const std::vector<CpuLevel> levels = probe_cpu_levels();
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
