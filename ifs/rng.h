// SPDX-License-Identifier: Apache-2.0
// Random numbers for the chaos game: small, fast, and splittable, so that every chunk of work
// draws from its own stream derived from (seed, chunk) and the result never depends on how
// chunks are spread over threads (docs/style.md rule 5).
#pragma once

#include <cstdint>
#include <vector>

namespace ifsfx {

// GCC's 128-bit integer, for the 64×64→128 multiplies below (__extension__ keeps -Wpedantic quiet).
__extension__ using uint128 = unsigned __int128;

// SplitMix64's finaliser: a bijective 64-bit mix, used to derive independent stream states.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The seed of stream `stream` of the run seeded with `seed`.
constexpr std::uint64_t stream_seed(std::uint64_t seed, std::uint64_t stream) noexcept {
  return mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ (stream * 0xd1b54a32d192ed03ULL + 1));
}

// wyrand: a counter-based generator (state advances by a constant, the output is a 64×64→128
// multiply-fold of it). One multiply per draw; passes BigCrush and PractRand.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) noexcept : state_(seed) {}

  std::uint64_t next() noexcept {
    state_ += 0xa0761d6478bd642fULL;
    const std::uint64_t a = state_, b = state_ ^ 0xe7037ed1a0b428dbULL;
    // The product's halves as two 64-bit values (the same bits): GCC 12 spilled the 128-bit
    // product of the one-expression form through the stack in the flame walks' draw loops
    // (two stores and a load a draw); now a mul and an imul, in registers.
    const auto hi = static_cast<std::uint64_t>((static_cast<uint128>(a) * b) >> 64);
    return hi ^ (a * b);
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; bias ≤ n / 2^64).
  std::uint32_t below(std::uint32_t n) noexcept {
    return static_cast<std::uint32_t>((static_cast<uint128>(next()) * n) >> 64);
  }

 private:
  std::uint64_t state_;
};

// Draws a map index with given probabilities in O(1) from one 64-bit random number (Walker's
// alias method: the high 32 bits pick a column, the low 32 bits decide between the column and its
// alias). Exact to 2^-32.
class MapPicker {
 public:
  MapPicker() = default;
  // `probabilities` must be ≥ 0 with a positive sum; they are normalised here.
  explicit MapPicker(const std::vector<double>& probabilities);

  std::uint32_t operator()(std::uint64_t r) const noexcept { return view()(r); }
  std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(n_); }

  // The tables by pointer, for hot loops that keep them in registers.
  struct View {
    std::uint64_t n;
    const std::uint32_t* threshold;
    const std::uint32_t* alias;
    std::uint32_t operator()(std::uint64_t r) const noexcept {
      const auto column = static_cast<std::uint32_t>(((r >> 32) * n) >> 32);
      return static_cast<std::uint32_t>(r) < threshold[column] ? column : alias[column];
    }
    // The same map by a mask instead of a branch, for loops of independent draws, where a
    // branch on a random bit is mispredicted half the time.
    std::uint32_t branch_free(std::uint64_t r) const noexcept {
      const auto column = static_cast<std::uint32_t>(((r >> 32) * n) >> 32);
      const std::uint32_t other = alias[column];
      const std::uint32_t own =
          0u - static_cast<std::uint32_t>(static_cast<std::uint32_t>(r) < threshold[column]);
      return other ^ ((column ^ other) & own);
    }
  };
  View view() const noexcept { return {n_, threshold_.data(), alias_.data()}; }

 private:
  std::uint64_t n_ = 0;
  std::vector<std::uint32_t> threshold_;  // P(column itself) · 2^32, saturated
  std::vector<std::uint32_t> alias_;
};

}  // namespace ifsfx
