// SPDX-License-Identifier: Apache-2.0
#include "plugins/frei0r/host.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::frei0r {

double seconds_from_host(double time, const void* caller) {
  Dl_info info{};
  if (caller != nullptr && dladdr(caller, &info) != 0 && info.dli_fname != nullptr &&
      std::strstr(info.dli_fname, "libavfilter") != nullptr)
    return time / 1000;
  return time;
}

std::int64_t whole_number(double value, const char* name, std::int64_t lo, std::int64_t hi) {
  if (!(value >= static_cast<double>(lo) && value <= static_cast<double>(hi)) ||
      value != std::floor(value))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: must be a whole number in [{}, {}] (got {})", name, lo, hi, value));
  return static_cast<std::int64_t>(value);
}

void Reporter::report(const std::string& message) {
  if (message == last_) return;
  last_ = message;
  std::fprintf(stderr, "frei0r %s: %s\n", plugin_, message.c_str());
  std::fflush(stderr);
}

}  // namespace ifsfx::frei0r
