// SPDX-License-Identifier: Apache-2.0
#include "engine/drift.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/rng.h"
#include "ifs/view.h"

namespace ifsfx::engine {

namespace {

// The gradient at lattice point i of a noise stream: uniform in [−1, 1], from a hash alone.
double gradient(std::uint64_t stream, std::int64_t i) {
  const std::uint64_t h = mix64(stream ^ mix64(static_cast<std::uint64_t>(i)));
  return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
}

// Lattice point i on a ring of `cells` points (0: no ring, the endless lattice).
std::int64_t wrap(std::int64_t i, std::int64_t cells) {
  if (cells <= 0) return i;
  const std::int64_t r = i % cells;
  return r < 0 ? r + cells : r;
}

// Perlin's 1-D gradient noise with the quintic fade: smooth (C²), zero at lattice points, about
// [−0.5, 0.5]. With cells > 0 the lattice is a ring of that many points: periodic in x.
double gradient_noise(double x, std::uint64_t stream, std::int64_t cells) {
  const double cell = std::floor(x);
  const auto i = static_cast<std::int64_t>(cell);
  const double f = x - cell;
  const double fade = f * f * f * (f * (f * 6 - 15) + 10);
  const double left = gradient(stream, wrap(i, cells)) * f;
  const double right = gradient(stream, wrap(i + 1, cells)) * (f - 1);
  return left + fade * (right - left);
}

// fBm with the slowest octave on a ring of `cycles` cells (0: endless), octave o on cycles · 2^o.
double octaves_sum(double x, std::int64_t cycles, std::uint64_t seed, std::uint64_t channel,
                   int octaves) {
  // Gradient noise is zero on its lattice, and the lattices of octaves 2^o apart share every
  // whole x: unshifted, every coefficient of every map would be back on its base value at once,
  // every 1/speed seconds (the animation "breathing" back to the preset). Each octave of each
  // channel is shifted by its own phase in [0, 1) instead, and the sum taken relative to x = 0,
  // so that t = 0 is still the base IFS.
  double sum = 0, at_zero = 0, amplitude = 1, norm = 0, frequency = 1;
  for (int o = 0; o < octaves; ++o) {
    const std::uint64_t stream = stream_seed(seed, channel * 64 + o);
    const double phase = static_cast<double>(mix64(~stream) >> 11) * 0x1.0p-53;
    const std::int64_t cells = cycles << o;
    sum += amplitude * gradient_noise(x * frequency + phase, stream, cells);
    at_zero += amplitude * gradient_noise(phase, stream, cells);
    norm += amplitude;
    amplitude *= 0.5;
    frequency *= 2;
  }
  if (norm <= 0) return 0;
  // Gradient noise spans about ±0.5, so 2·sum/norm and 2·at_zero/norm lie in about [−1, 1] and
  // their difference in ±(1 + |offset|): scaled back by that, the result stays in [−1, 1].
  const double offset = 2 * at_zero / norm;
  return (2 * sum / norm - offset) / (1 + std::abs(offset));
}

}  // namespace

double fbm(double x, std::uint64_t seed, std::uint64_t channel, int octaves) {
  return octaves_sum(x, 0, seed, channel, octaves);
}

double fbm_periodic(double x, std::int64_t cycles, std::uint64_t seed, std::uint64_t channel,
                    int octaves) {
  cycles = std::max<std::int64_t>(cycles, 1);
  // x on [0, cycles): a whole period later is the same point, bit for bit.
  const double period = static_cast<double>(cycles);
  x -= std::floor(x / period) * period;
  if (!(x < period)) x = 0;
  return octaves_sum(x, cycles, seed, channel, octaves);
}

Ifs drift(const Ifs& base, double t, const DriftOptions& options) {
  if (!(options.amount >= 0 && options.amount <= kMaxDriftAmount))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("drift amount: must be in [0, {:g}] (got {})", kMaxDriftAmount,
                            options.amount));
  if (!(options.speed >= 0 && options.speed <= kMaxDriftSpeed))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("drift speed: must be in [0, {:g}] (got {})", kMaxDriftSpeed, options.speed));
  if (!std::isfinite(t))
    throw Error(ErrorKind::invalid_argument, fmt::format("drift: time must be finite (got {})", t));
  if (options.octaves < 1 || options.octaves > 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("drift octaves: must be in 1..16 (got {})", options.octaves));
  if (!(options.loop >= 0 && options.loop <= kMaxDriftLoop))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("drift loop: must be in [0, {:g}] seconds (got {})", kMaxDriftLoop,
                            options.loop));
  const auto attractor_extent = [&] {
    const Box bounds = attractor_bounds(base, options.seed);
    return std::max({bounds.width(), bounds.height(), 1e-9});
  };
  const double extent = options.extent ? *options.extent : attractor_extent();
  // A loop: time as the fraction u of the loop, on a noise of whole cycles per loop.
  const bool loop = options.loop > 0 && options.speed > 0;
  const std::int64_t cycles =
      loop ? std::max<std::int64_t>(1, std::llround(options.loop * options.speed)) : 0;
  double u = loop ? t / options.loop : 0;
  u -= std::floor(u);
  const double x = loop ? u * static_cast<double>(cycles) : t * options.speed;
  const auto noise = [&](std::uint64_t channel) {
    return loop ? fbm_periodic(x, cycles, options.seed, channel, options.octaves)
                : fbm(x, options.seed, channel, options.octaves);
  };
  Ifs out = base;
  for (std::size_t n = 0; n < base.size(); ++n) {
    const AffineMap& f = base.maps[n];
    auto k = f.coefficients();
    for (std::size_t j = 0; j < 6; ++j) {
      const double scale = j < 4 ? options.amount : options.amount * extent;
      k[j] += scale * noise(n * 6 + j);
    }
    AffineMap g = AffineMap::from_coefficients(k);
    // Keep the map contractive: scale its linear part back to the cap (translation kept).
    const double cap = std::max(options.max_contraction, f.contraction());
    const double s = g.contraction();
    if (s > cap) {
      const double r = cap / s;
      g.a *= r;
      g.b *= r;
      g.c *= r;
      g.d *= r;
    }
    out.maps[n] = g;
  }
  return out;
}

}  // namespace ifsfx::engine
