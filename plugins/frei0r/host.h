// SPDX-License-Identifier: Apache-2.0
// What the frei0r plugins need to know about their hosts, and how they talk back to them.
#pragma once

#include <cstdint>
#include <string>

namespace ifsfx::frei0r {

// The nominal frame rate of a host's time line: frei0r does not tell a plugin the stream's rate,
// so an animation keyed to frame numbers reads the time at this rate (frames between two of its
// frames are blended, never dropped).
inline constexpr double nominal_frame_rate = 25;

// A plugin's `rate` parameter: frames per second in (0, 1000], or Error{invalid_argument}
// "rate: must be in (0, 1000] frames per second (got X)".
double frame_rate_parameter(double value);

// A parameter that must be a whole number in [lo, hi] (frei0r has doubles only): the value, or
// Error{invalid_argument} "NAME: must be a whole number in [lo, hi] (got X)".
std::int64_t whole_number(double value, const char* name, std::int64_t lo, std::int64_t hi);

// One line "frei0r PLUGIN: MESSAGE" on stderr, printed once per different message: a bad
// parameter is reported when it is set, not on every frame after it.
class Reporter {
 public:
  explicit Reporter(const char* plugin) : plugin_(plugin) {}
  void report(const std::string& message);
  // The parameters are good again: the next fault is reported even if it repeats the last one.
  void clear() { last_.clear(); }

 private:
  const char* plugin_;
  std::string last_;
};

}  // namespace ifsfx::frei0r
