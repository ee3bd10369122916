// SPDX-License-Identifier: Apache-2.0
#include "engine/drift.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::engine {
namespace {

// Barnsley's fern (its stem map is singular).
Ifs fern() {
  Ifs f;
  f.name = "fern";
  f.maps = {{0, 0, 0, 0.16, 0, 0},
            {0.85, 0.04, -0.04, 0.85, 0, 1.6},
            {0.2, -0.26, 0.23, 0.22, 0, 1.6},
            {-0.15, 0.28, 0.26, 0.24, 0, 0.44}};
  return f;
}

TEST(drift, zero_amount_keeps_the_ifs) {
  const Ifs base = fern();
  const Ifs same = drift(base, 3.7, {.amount = 0});
  for (std::size_t n = 0; n < base.size(); ++n) EXPECT_EQ(same.maps[n], base.maps[n]);
}

TEST(drift, same_seed_and_time_give_the_same_maps_and_time_moves_them) {
  const Ifs base = fern();
  const DriftOptions o{.amount = 0.1, .seed = 42};
  const Ifs a = drift(base, 1.25, o), b = drift(base, 1.25, o), later = drift(base, 4.0, o);
  const Ifs other_seed = drift(base, 1.25, {.amount = 0.1, .seed = 43});
  for (std::size_t n = 0; n < base.size(); ++n) EXPECT_EQ(a.maps[n], b.maps[n]);
  EXPECT_NE(a.maps[1], later.maps[1]);
  EXPECT_NE(a.maps[1], other_seed.maps[1]);
}

TEST(drift, maps_stay_contractive_under_large_drift) {
  const Ifs base = fern();
  for (double t = 0; t < 20; t += 0.37) {
    const Ifs d = drift(base, t, {.amount = 2.0, .speed = 1.0});
    for (std::size_t n = 0; n < d.size(); ++n) {
      EXPECT_LE(d.maps[n].contraction(), std::max(0.95, base.maps[n].contraction()) + 1e-12);
      EXPECT_TRUE(d.maps[n].finite());
    }
  }
}

TEST(drift, motion_is_smooth_and_bounded) {
  // fBm of gradient noise is continuous: a 1 ms step moves a coefficient by far less than the
  // amount, while over seconds it explores about ±amount.
  double largest = 0, biggest_step = 0;
  double previous = fbm(0, 7, 3, 4);
  for (int i = 1; i <= 20000; ++i) {
    const double v = fbm(i * 0.001, 7, 3, 4);
    largest = std::max(largest, std::abs(v));
    biggest_step = std::max(biggest_step, std::abs(v - previous));
    previous = v;
  }
  EXPECT_LE(largest, 1.0);
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(biggest_step, 0.05);
}

TEST(drift, time_zero_is_the_base_and_whole_cycles_are_not) {
  // Gradient noise vanishes on its lattice, and octaves of doubling frequency share every whole
  // x: without each octave's own phase, every coefficient would be back on its base value at
  // t = k / speed, all at once, and the animation would pass through the preset on a beat.
  const Ifs base = fern();
  const DriftOptions o{.amount = 0.1, .speed = 1, .seed = 5};
  const Ifs start = drift(base, 0, o);
  for (std::size_t n = 0; n < base.size(); ++n) EXPECT_EQ(start.maps[n], base.maps[n]);
  for (const double t : {1.0, 2.0, 3.0, 5.0, 99.0}) {
    const Ifs d = drift(base, t, o);
    double moved = 0;
    for (std::size_t n = 0; n < base.size(); ++n) {
      const auto a = base.maps[n].coefficients(), b = d.maps[n].coefficients();
      for (std::size_t j = 0; j < 6; ++j) moved = std::max(moved, std::abs(a[j] - b[j]));
    }
    EXPECT_GT(moved, 0.01) << "t = " << t << " is the base IFS again";
  }
  for (std::uint64_t channel = 0; channel < 24; ++channel) {
    EXPECT_EQ(fbm(0, 5, channel, 4), 0.0);
    EXPECT_NE(fbm(1, 5, channel, 4), 0.0);
  }
}

TEST(drift, noise_stays_within_one_on_every_channel) {
  for (std::uint64_t channel = 0; channel < 64; ++channel)
    for (int i = 0; i <= 4000; ++i) {
      const double v = fbm(i * 0.01, 11, channel, 4);
      ASSERT_LE(std::abs(v), 1.0) << "channel " << channel << ", x = " << i * 0.01;
    }
}

TEST(drift, bad_options_are_refused) {
  EXPECT_THROW(drift(fern(), 0, {.amount = -1}), Error);
  EXPECT_THROW(drift(fern(), 0, {.speed = std::nan("")}), Error);
  EXPECT_THROW(drift(fern(), 0, {.loop = -1}), Error);
  EXPECT_THROW(drift(fern(), 0, {.loop = std::nan("")}), Error);
}

// The largest change of any coefficient between two IFSs.
double moved(const Ifs& a, const Ifs& b) {
  double m = 0;
  for (std::size_t n = 0; n < a.size(); ++n) {
    const auto p = a.maps[n].coefficients(), q = b.maps[n].coefficients();
    for (std::size_t j = 0; j < 6; ++j) m = std::max(m, std::abs(p[j] - q[j]));
  }
  return m;
}

TEST(drift_loop, time_T_is_time_0_bit_for_bit_and_every_time_repeats) {
  // 48 frames at 25 fps: 1.92 s; at 0.2 cycles per second the slowest octave makes one cycle.
  const Ifs base = fern();
  const DriftOptions o{.amount = 0.1, .speed = 0.2, .seed = 5, .loop = 1.92};
  for (std::size_t n = 0; n < base.size(); ++n)
    EXPECT_EQ(drift(base, 1.92, o).maps[n], base.maps[n]);
  for (int frame = 0; frame < 48; ++frame) {
    const double t = frame / 25.0;
    const Ifs a = drift(base, t, o), b = drift(base, t + 1.92, o), c = drift(base, t + 3 * 1.92, o);
    EXPECT_LT(moved(a, b), 1e-12) << frame;
    EXPECT_LT(moved(a, c), 1e-12) << frame;
  }
  EXPECT_GT(moved(base, drift(base, 0.96, o)), 0.01);  // it does move in between
}

TEST(drift_loop, the_step_from_the_last_frame_back_to_the_first_is_like_any_other) {
  const Ifs base = fern();
  for (const double speed : {0.2, 1.0, 3.0}) {
    const DriftOptions o{.amount = 0.1, .speed = speed, .seed = 9, .loop = 1.92};
    std::vector<Ifs> frames;
    for (int frame = 0; frame <= 48; ++frame) frames.push_back(drift(base, frame / 25.0, o));
    double smallest = 1e9, largest = 0;
    for (int frame = 0; frame + 1 < 48; ++frame) {
      const double step = moved(frames[frame], frames[frame + 1]);
      smallest = std::min(smallest, step);
      largest = std::max(largest, step);
    }
    const double wrap = moved(frames[47], frames[48]);
    EXPECT_LT(moved(frames[48], frames[0]), 1e-12);
    EXPECT_LE(wrap, largest) << "speed " << speed;
    EXPECT_GE(wrap, 0.5 * smallest) << "speed " << speed;
  }
}

TEST(drift_loop, periodic_noise_wraps_smoothly_stays_in_range_and_starts_at_zero) {
  for (const std::int64_t cycles : {1, 2, 5}) {
    EXPECT_EQ(fbm_periodic(0, cycles, 3, 1, 4), 0.0);
    double largest = 0, biggest_step = 0;
    double previous = fbm_periodic(0, cycles, 3, 1, 4);
    for (int i = 1; i <= 4000; ++i) {
      const double x = i * 0.001 * static_cast<double>(cycles);
      const double v = fbm_periodic(x, cycles, 3, 1, 4);
      largest = std::max(largest, std::abs(v));
      biggest_step = std::max(biggest_step, std::abs(v - previous));
      previous = v;
      ASSERT_LE(std::abs(v), 1.0);
    }
    EXPECT_GT(largest, 0.1) << cycles;
    EXPECT_LT(biggest_step, 0.05) << cycles;
    // Across the wrap: the last step before x = cycles and the first after it are as small.
    const double c = static_cast<double>(cycles);
    EXPECT_NEAR(fbm_periodic(c - 1e-6, cycles, 3, 1, 4), fbm_periodic(1e-6, cycles, 3, 1, 4), 1e-4);
    EXPECT_EQ(fbm_periodic(c + 0.375, cycles, 3, 1, 4), fbm_periodic(0.375, cycles, 3, 1, 4));
  }
}

TEST(drift_loop, without_speed_a_loop_keeps_the_ifs_still) {
  const Ifs base = fern();
  const Ifs d = drift(base, 0.7, {.amount = 0.1, .speed = 0, .loop = 2});
  for (std::size_t n = 0; n < base.size(); ++n) EXPECT_EQ(d.maps[n], base.maps[n]);
}

}  // namespace
}  // namespace ifsfx::engine
