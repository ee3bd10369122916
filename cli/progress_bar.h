// SPDX-License-Identifier: Apache-2.0
// The progress bar of the long commands (`filter`, `dataset`): on a terminal one line redrawn in
// place, "[#####.....] 120/400 frames  25.0 fps  ETA 0:11", otherwise a plain line per report.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace ifsfx::app {

// "m:ss" or "h:mm:ss"; "--:--" for a negative (unknown) time.
std::string clock_text(double seconds);

class ProgressBar {
 public:
  // `unit` counts the work ("frames", "images"), `rate_unit` its rate ("fps", "images/s").
  ProgressBar(bool tty, std::string unit, std::string rate_unit)
      : tty_(tty), unit_(std::move(unit)), rate_unit_(std::move(rate_unit)) {}

  // One report: `total` < 0 when unknown; the last one (`finished`) ends the line.
  void operator()(std::int64_t done, std::int64_t total, double seconds, bool finished) const;

 private:
  bool tty_;
  std::string unit_, rate_unit_;
};

}  // namespace ifsfx::app
