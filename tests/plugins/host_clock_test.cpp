// SPDX-License-Identifier: Apache-2.0
// HostClock: the times hosts really pass (probed in FFmpeg 5.1.9, MLT 7.12, GStreamer 1.22; see
// plugins_e2e.sh host_times) and the frames a plugin counts when they cannot be used.
#include "plugins/frei0r/host_clock.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace ifsfx::frei0r {
namespace {

// FFmpeg 5.1's frei0r filter for a frame that lost its timestamp: AV_NOPTS_VALUE · time_base ·
// 1000, with Matroska's time base (1/1000) and after `fps=25` (1/25).
constexpr double nopts_mkv = static_cast<double>(INT64_MIN);
constexpr double nopts_fps25 = static_cast<double>(INT64_MIN) * 1000 / 25;
// GStreamer's GST_CLOCK_TIME_NONE / GST_SECOND.
constexpr double gst_none = 18446744073.709551615;

std::vector<HostClock::Reading> read(HostClock clock, const std::vector<double>& times,
                                     double rate = 25) {
  std::vector<HostClock::Reading> out;
  for (double t : times) out.push_back(clock.next(t, rate));
  return out;
}

TEST(host_clock, good_seconds_are_used_as_they_are_even_backwards) {
  const auto r = read(HostClock(TimeUnit::seconds), {0, 1.5, 0.2, 7});
  const double expected[] = {0, 1.5, 0.2, 7};
  for (std::size_t k = 0; k < r.size(); ++k) {
    EXPECT_DOUBLE_EQ(r[k].seconds, expected[k]) << k;
    EXPECT_FALSE(r[k].counted) << k;
  }
}

TEST(host_clock, libavfilter_milliseconds_become_seconds) {
  const auto r = read(HostClock(TimeUnit::milliseconds), {0, 40, 80, 120});
  for (std::size_t k = 0; k < r.size(); ++k) {
    EXPECT_DOUBLE_EQ(r[k].seconds, 0.04 * static_cast<double>(k)) << k;
    EXPECT_FALSE(r[k].counted);
  }
}

TEST(host_clock, ffmpeg_nopts_counts_frames_at_the_fallback_rate) {
  for (double nopts : {nopts_mkv, nopts_fps25}) {
    const auto r = read(HostClock(TimeUnit::milliseconds), {nopts, nopts, nopts, nopts});
    for (std::size_t k = 0; k < r.size(); ++k) {
      EXPECT_TRUE(r[k].counted) << k;
      EXPECT_DOUBLE_EQ(r[k].rate, 25);
      EXPECT_DOUBLE_EQ(r[k].seconds, static_cast<double>(k) / 25) << k;
    }
    const auto thirty = read(HostClock(TimeUnit::milliseconds), {nopts, nopts, nopts}, 30);
    EXPECT_DOUBLE_EQ(thirty[2].seconds, 2.0 / 30);
    EXPECT_DOUBLE_EQ(thirty[2].rate, 30);
  }
}

TEST(host_clock, no_time_markers_and_non_numbers_are_not_trusted) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {gst_none, std::nan(""), inf, -inf, -0.04, 3.1e9}) {
    const auto r = read(HostClock(TimeUnit::seconds), {bad, bad});
    EXPECT_TRUE(r[0].counted && r[1].counted) << bad;
    EXPECT_DOUBLE_EQ(r[1].seconds, 1.0 / 25) << bad;
  }
}

TEST(host_clock, counting_goes_on_from_the_last_good_time_at_the_rate_it_showed) {
  // 30 fps shown by the host's good times (0, 33.3, 66.7 ms), then it stops giving them: the
  // count goes on at 30 fps from the last good time, whatever the fallback says.
  const auto r =
      read(HostClock(TimeUnit::milliseconds), {0, 100.0 / 3, 200.0 / 3, nopts_mkv, nopts_mkv}, 25);
  EXPECT_FALSE(r[2].counted);
  EXPECT_TRUE(r[3].counted);
  EXPECT_NEAR(r[3].rate, 30, 1e-9);
  EXPECT_NEAR(r[3].seconds, 0.1, 1e-12);
  EXPECT_NEAR(r[4].seconds, 4.0 / 30, 1e-12);
}

TEST(host_clock, a_good_time_after_bad_ones_is_used) {
  const auto r = read(HostClock(TimeUnit::milliseconds), {nopts_mkv, nopts_mkv, 5000});
  EXPECT_DOUBLE_EQ(r[1].seconds, 0.04);
  EXPECT_FALSE(r[2].counted);
  EXPECT_DOUBLE_EQ(r[2].seconds, 5);
}

TEST(host_clock, libavfilter_passing_seconds_is_recognised_by_its_steps) {
  // A fork of FFmpeg that passes seconds (pts · time_base): steps of 0.04 cannot be milliseconds
  // (that would be 25,000 fps). Frame 0 is 0 either way.
  const auto r = read(HostClock(TimeUnit::milliseconds), {0, 0.04, 0.08, 2.5});
  EXPECT_DOUBLE_EQ(r[1].seconds, 0.04);
  EXPECT_DOUBLE_EQ(r[2].seconds, 0.08);
  EXPECT_DOUBLE_EQ(r[3].seconds, 2.5);
  // Seconds hosts are never switched: a 0.2 fps slide show steps by 5 s.
  const auto slides = read(HostClock(TimeUnit::seconds), {0, 5, 10});
  EXPECT_DOUBLE_EQ(slides[2].seconds, 10);
}

TEST(host_clock, a_rate_that_is_not_a_frame_rate_counts_at_the_default) {
  for (double rate : {0.0, -1.0, 2000.0, std::nan("")}) {
    const auto r = read(HostClock(TimeUnit::seconds), {nopts_mkv, nopts_mkv}, rate);
    EXPECT_DOUBLE_EQ(r[1].seconds, 1.0 / default_count_rate) << rate;
    EXPECT_DOUBLE_EQ(r[1].rate, default_count_rate) << rate;
  }
}

}  // namespace
}  // namespace ifsfx::frei0r
