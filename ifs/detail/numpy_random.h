// SPDX-License-Identifier: Apache-2.0
// NumPy's legacy global generator (numpy.random.seed, random, randint, uniform: RandomState over
// MT19937), draw for draw, for the FractalDB reference generator's chaos game and category search
// (fractaldb/render.h, fractaldb/search.h), which seed it and draw from it. MT19937 is
// specified by the C++ standard (std::mt19937 seeded with s is init_genrand(s), as
// numpy.random.seed(s) for an integer s < 2^32); the conversions below are NumPy's.
#pragma once

#include <cstdint>
#include <random>

namespace ifsfx::detail {

class NumpyRandom {
 public:
  explicit NumpyRandom(std::uint32_t seed) : mt_(seed) {}

  // numpy.random.random(): 53 random bits from two 32-bit draws, in [0, 1).
  double random() {
    const auto a = mt_() >> 5;
    const auto b = mt_() >> 6;
    return (a * 67108864.0 + b) / 9007199254740992.0;
  }

  // numpy.random.uniform(low, high): low + (high - low) · random().
  double uniform(double low, double high) { return low + (high - low) * random(); }

  // numpy.random.randint(low, high) for high − low ≤ 2^32: uniform in [low, high), drawn as
  // RandomState does, by masked rejection of 32-bit draws.
  std::int64_t randint(std::int64_t low, std::int64_t high) {
    const auto range = static_cast<std::uint64_t>(high - low - 1);
    if (range == 0) return low;
    std::uint64_t mask = range;
    for (int shift = 1; shift < 64; shift *= 2) mask |= mask >> shift;
    std::uint64_t v = 0;
    do v = mt_() & mask;
    while (v > range);
    return low + static_cast<std::int64_t>(v);
  }

  // Skips what `count` calls of random() would draw.
  void skip_random(std::uint64_t count) { mt_.discard(2 * count); }

 private:
  // std::mt19937 with 32-bit words (the standard's keeps them in uint_fast32_t, 64 bits here):
  // the same numbers, generated faster.
  std::mersenne_twister_engine<std::uint32_t, 32, 624, 397, 31, 0x9908b0df, 11, 0xffffffff, 7,
                               0x9d2c5680, 15, 0xefc60000, 18, 1812433253>
      mt_;
};

}  // namespace ifsfx::detail
