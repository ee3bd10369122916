// SPDX-License-Identifier: Apache-2.0
#include "plugins/frei0r/host_clock.h"

#include <dlfcn.h>

#include <cmath>
#include <cstring>

namespace ifsfx::frei0r {

TimeUnit host_time_unit(const void* caller) {
  Dl_info info{};
  if (caller != nullptr && dladdr(caller, &info) != 0 && info.dli_fname != nullptr &&
      std::strstr(info.dli_fname, "libavfilter") != nullptr)
    return TimeUnit::milliseconds;
  return TimeUnit::seconds;
}

HostClock::Reading HostClock::next(double host_time, double fallback_rate) {
  const std::int64_t frame = frame_++;
  const bool good =
      std::isfinite(host_time) && host_time >= 0 && seconds_of(host_time) < latest_host_time;
  if (good) {
    if (good_ == 0) {
      first_ = {frame, host_time};
    } else if (unit_ == TimeUnit::milliseconds && frame == last_.frame + 1 &&
               host_time > last_.raw && host_time - last_.raw < 2) {
      unit_ = TimeUnit::seconds;
    }
    good_ = good_ < 2 ? good_ + 1 : 2;
    last_ = {frame, host_time};
    return {seconds_of(host_time), false};
  }
  // Counting from the last good time (or from frame 0 at 0 s).
  double rate = is_frame_rate(fallback_rate) ? fallback_rate : default_count_rate;
  if (good_ == 2 && last_.raw > first_.raw) {
    const double shown =
        static_cast<double>(last_.frame - first_.frame) / seconds_of(last_.raw - first_.raw);
    if (is_frame_rate(shown)) rate = shown;
  }
  const double from = good_ > 0 ? seconds_of(last_.raw) : 0;
  return {from + static_cast<double>(frame - (good_ > 0 ? last_.frame : 0)) / rate, true, rate};
}

}  // namespace ifsfx::frei0r
