// SPDX-License-Identifier: Apache-2.0
// What the flame renderer's plot costs a hit (flame/detail/batch_variations.h, flame_plot), and
// what the memory traffic alone of the same hits costs: the floor under any plot of 32-bit r, g,
// b, a sums (issue 31's speed item). The hits are a Sierpinski gasket's chaos game (three maps,
// colour speed 1/2) on square rasters of bins from 256 KB to 16 MB, in the walk's batches of 256
// (kBatchLanes); per raster it prints, in thread CPU ns a hit (best of 3 rounds of ~0.2 s):
//   floor   bins[at] += palette[k][⌊256c⌋], nothing else (a step palette's look-up and the add)
//   plot    the renderer's kernel at the level ifs/cpu.h picks, with a linear palette (two entries
//           mixed, the wrap check)
//   plot/1  the same kernel with a step palette
//   build/release/bench/flame_plot_bench          (IFSFX_CPU=scalar|avx2 forces a level)
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "bench/thread_clock.h"
#include "flame/detail/batch_variations.h"
#include "ifs/cpu.h"
#include "ifs/rng.h"

namespace {

using namespace ifsfx;
using U4 = std::uint32_t __attribute__((vector_size(16)));

using bench::seconds_per_call;

// The hits of a gasket's orbit on a side×side raster: bin, map and colour coordinate of each.
struct Hits {
  std::vector<std::uint32_t> at, k;
  std::vector<double> c;
};

Hits gasket(int side, std::size_t n) {
  Hits h;
  Rng rng(stream_seed(1, static_cast<std::uint64_t>(side)));
  double x = 0.3, y = 0.3, c = 0.5;
  for (std::size_t i = 0; i < n + 20; ++i) {
    const auto k = static_cast<std::uint32_t>(rng.next() % 3);
    x = 0.5 * x + (k == 1 ? 0.5 : 0);
    y = 0.5 * y + (k == 2 ? 0.5 : 0);
    c = 0.5 * c + 0.25 * k;
    if (i < 20) continue;  // burn-in
    const auto bx = static_cast<std::uint32_t>(x * side), by = static_cast<std::uint32_t>(y * side);
    h.at.push_back(by * static_cast<std::uint32_t>(side) + bx);
    h.k.push_back(k);
    h.c.push_back(c);
  }
  return h;
}

}  // namespace

int main() {
  constexpr std::size_t kHits = std::size_t{1} << 20, kBatch = flame::detail::kBatchLanes;
  // Three xforms' palettes in the renderer's units (an entry at most 2¹⁶).
  std::array<std::array<U4, 256>, 3> palettes{};
  for (std::uint32_t k = 0; k < 3; ++k)
    for (std::uint32_t e = 0; e < 256; ++e)
      palettes[k][e] = U4{(e * 251 + k * 7919) % 65536, (e * 97) % 65536, 65535 - e * 200, 65536};
  const std::array<const std::uint32_t*, 3> tables{
      reinterpret_cast<const std::uint32_t*>(palettes[0].data()),
      reinterpret_cast<const std::uint32_t*>(palettes[1].data()),
      reinterpret_cast<const std::uint32_t*>(palettes[2].data())};
  const flame::detail::PlotFunction plot = flame::detail::plot_function(cpu_level());
  fmt::print("flame plot, {} hits of a gasket's orbit, batches of {}, kernels {}\n", kHits, kBatch,
             to_string(cpu_level()));
  fmt::print("{:>6} {:>9} {:>9} {:>9} {:>9}\n", "side", "bins MB", "floor", "plot", "plot/1");
  for (const int side : {128, 256, 512, 1024}) {
    const Hits h = gasket(side, kHits);
    std::vector<std::uint32_t> bins(4 * static_cast<std::size_t>(side) * side);
    const double floor = seconds_per_call([&] {
      auto* b = reinterpret_cast<U4*>(bins.data());
      for (std::size_t i = 0; i < kHits; ++i) {
        const auto e = std::min<std::size_t>(static_cast<std::size_t>(h.c[i] * 256), 255);
        b[h.at[i]] += palettes[h.k[i]][e];
      }
    });
    const auto kernel = [&](bool linear) {
      const flame::detail::PlotTables t{tables.data(), linear};
      return seconds_per_call([&] {
        for (std::size_t from = 0; from < kHits; from += kBatch) {
          // A wrapped sum stops the kernel after that hit; the renderer logs a carry there.
          for (std::size_t j = 0; j < kBatch;) {
            unsigned wrapped = 0;
            j = plot(t, bins.data(), j, kBatch, nullptr, h.at.data() + from, h.k.data() + from,
                     h.c.data() + from, &wrapped);
          }
        }
      });
    };
    const double linear = kernel(true), step = kernel(false);
    const double mb = 16.0 * side * side / (1 << 20), n = kHits;
    fmt::print("{:>6} {:>9.2f} {:>9.2f} {:>9.2f} {:>9.2f}{}\n", side, mb, 1e9 * floor / n,
               1e9 * linear / n, 1e9 * step / n, bins[0] == 1 ? " " : "");
  }
  return 0;
}
