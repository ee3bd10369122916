// SPDX-License-Identifier: Apache-2.0
#include "cli/progress_bar.h"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

namespace ifsfx::app {

std::string clock_text(double seconds) {
  if (seconds < 0) return "--:--";
  const auto s = static_cast<long>(seconds + 0.5);
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{}:{:02}", s / 60, s % 60);
}

void ProgressBar::operator()(std::int64_t done, std::int64_t total, double seconds,
                             bool finished) const {
  const std::string counts =
      total >= 0 ? fmt::format("{}/{} {}", done, total, unit_) : fmt::format("{} {}", done, unit_);
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  const double eta = total < 0 || done <= 0 ? -1 : static_cast<double>(total - done) / rate;
  const std::string rate_text = fmt::format("{:.1f} {}", rate, rate_unit_);
  if (tty_) {
    std::string bar;
    if (total > 0) {
      constexpr int width = 30;
      const auto filled =
          static_cast<int>(width * std::min<double>(1.0, static_cast<double>(done) / total));
      bar.reserve(width + 3);
      bar += '[';
      bar.append(static_cast<std::size_t>(filled), '#');
      bar.append(static_cast<std::size_t>(width - filled), '.');
      bar += "] ";
    }
    fmt::print(stderr, "\r{}{}  {}  ETA {}  ", bar, counts, rate_text, clock_text(eta));
    if (finished) std::fputs("\n", stderr);
  } else {
    fmt::print(stderr, "{}  {}  elapsed {}  ETA {}\n", counts, rate_text, clock_text(seconds),
               clock_text(eta));
  }
  std::fflush(stderr);
}

}  // namespace ifsfx::app
