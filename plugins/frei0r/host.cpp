// SPDX-License-Identifier: Apache-2.0
#include "plugins/frei0r/host.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "ifs/error.h"
#include "plugins/frei0r/host_clock.h"

namespace ifsfx::frei0r {

double frame_rate_parameter(double value) {
  if (!is_frame_rate(value))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("rate: must be in (0, 1000] frames per second (got {})", value));
  return value;
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
