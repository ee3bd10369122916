// SPDX-License-Identifier: Apache-2.0
// The time of each frame, read from a host's clock only where the clock can be trusted.
//
// frei0r hands a plugin one number per frame, f0r_update's `time`, and nothing else about the
// stream. Hosts get it wrong in ways a plugin meets in the wild: FFmpeg 5.1's frei0r filter passes
// AV_NOPTS_VALUE through its milliseconds formula (-9.2e18, or -3.7e20 after `fps=25`) for every
// frame whose rows it had to copy, i.e. whenever the width is not a multiple of 64 pixels; a
// GStreamer buffer without a timestamp reads as 1.8e10 s (GST_CLOCK_TIME_NONE). An animation keyed
// on such a time freezes at one wrong picture. HostClock recognises the times no host can mean and
// then counts frames instead (docs/frei0r.md, "Frame times").
#pragma once

#include <cstdint>

namespace ifsfx::frei0r {

// What a host means by f0r_update's `time`. The frei0r API says seconds, and MLT and GStreamer
// pass seconds; FFmpeg's frei0r and frei0r_src filters pass milliseconds (libavfilter's
// vf_frei0r.c: pts · time_base · 1000, read in FFmpeg 5.1 and in its current source).
enum class TimeUnit { seconds, milliseconds };

// The unit of the host that called f0r_update from `caller` (its return address): a call from
// inside libavfilter is FFmpeg's.
TimeUnit host_time_unit(const void* caller);

// The latest time a host can mean, in seconds: beyond it the number is a "no time" marker
// (GStreamer's GST_CLOCK_TIME_NONE is 1.8e10 s), not a place in a clip (3e9 s is 95 years).
inline constexpr double latest_host_time = 3e9;

// The frames per second a plugin counts at when its host gives no usable times and the plugin's
// `rate` parameter is not set: the nominal rate of host.h, and the CLI's default for image
// sequences.
inline constexpr double default_count_rate = 25;
inline bool is_frame_rate(double fps) {
  return fps > 0 && fps <= 1000;
}

// One instance's clock. Call next() once for each frame the host asks for, in the host's order.
class HostClock {
 public:
  // `unit`: what the host's times are in, as far as the caller can tell (host_time_unit).
  explicit HostClock(TimeUnit unit) : unit_(unit) {}

  struct Reading {
    double seconds = 0;    // the frame's time
    bool counted = false;  // true: the host's time could not be used; `seconds` counts frames
    double rate = 0;       // when counted: the frames per second counted at
  };

  // The time of the next frame. A host time that is finite, not negative (a scrub never goes
  // before the start, and every NOPTS pattern is negative) and before latest_host_time is used as
  // it is, in its unit; backwards steps are honoured, as an editor's scrub. Any other time is
  // replaced by counting frames from the last good one: at the rate the host's good times showed
  // (their frames over their seconds), or, with fewer than two good times, `fallback_rate` frames
  // per second (default_count_rate where it is not is_frame_rate). A host in libavfilter whose
  // good times step by less than 2 between two frames passes seconds, not milliseconds (that would
  // be over 500 fps; forks of FFmpeg pass seconds): the unit is corrected from then on.
  Reading next(double host_time, double fallback_rate);

 private:
  struct Mark {
    std::int64_t frame = 0;
    double raw = 0;  // in the host's unit, as passed
  };
  double seconds_of(double raw) const { return unit_ == TimeUnit::milliseconds ? raw / 1000 : raw; }

  TimeUnit unit_;
  std::int64_t frame_ = 0;  // frames asked for so far
  int good_ = 0;            // good host times seen (counted up to 2)
  Mark first_;              // the first good time
  Mark last_;               // the latest good time
};

}  // namespace ifsfx::frei0r
