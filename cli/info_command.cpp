// SPDX-License-Identifier: Apache-2.0
// `ifsfx info` and `ifsfx --version`: the version, how this binary was built, and the kernel
// level it runs at on this machine (ifs/cpu.h).
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>
#include <opencv2/core/version.hpp>

#include "cli/commands.h"
#include "ifs/cpu.h"

namespace ifsfx::app {

std::string version_text() {
  std::string levels;
  for (CpuLevel level : supported_cpu_levels())
    levels += fmt::format("{}{}", levels.empty() ? "" : ", ", to_string(level));
  const char* forced = std::getenv("IFSFX_CPU");
  const bool is_forced = forced != nullptr && *forced != '\0';
  return fmt::format("ifsfx {} ({} build, {})\nkernels: {} ({})\n", IFSFX_VERSION, IFSFX_BUILD_TYPE,
                     IFSFX_NATIVE_BUILD ? "tuned for the build machine's CPU (-march=native)"
                                        : "portable x86-64, kernels chosen at run time",
                     to_string(cpu_level()),
                     is_forced
                         ? fmt::format("forced by IFSFX_CPU={}; this CPU runs {}", forced, levels)
                         : fmt::format("this CPU runs {}; IFSFX_CPU=scalar|avx2|avx512 "
                                       "forces one",
                                       levels));
}

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "info", "Show the version, the build, and the kernel level (SIMD instruction set) used here");
  cmd->callback([] {
    const std::string text =
        version_text() + fmt::format("compiler: {}\nOpenCV: {}\n", __VERSION__, CV_VERSION);
    std::fputs(text.c_str(), stdout);
  });
}

}  // namespace ifsfx::app
