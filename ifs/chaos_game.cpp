// SPDX-License-Identifier: Apache-2.0
#include "ifs/chaos_game.h"

#include <algorithm>
#include <cmath>

#include "ifs/detail/preconditions.h"
#include "ifs/detail/walkers.h"
#include "ifs/parallel.h"

namespace ifsfx {

int default_burn_in(const Ifs& ifs) {
  // s^k < 1e-9: any start is then within 1e-9 of the attractor (relative to its size). IFSs that
  // only contract on average use their mean log contraction per step instead of log s.
  const double s = ifs.contraction();
  const double rate = s < 1 ? std::log(std::max(s, 1e-300)) : mean_log_contraction(ifs);
  if (!(rate < 0)) return 100000;
  const double k = std::ceil(std::log(1e-9) / rate);
  return static_cast<int>(std::clamp(k, 64.0, 100000.0));
}

std::vector<Sample> chaos_game_samples(const Ifs& ifs, std::size_t count,
                                       const ChaosGameOptions& options) {
  detail::check_chaos_game({.ifs = ifs, .threads = options.threads, .burn_in = options.burn_in});
  std::vector<Sample> out(count);
  const detail::MapTable maps(ifs);
  const MapPicker pick(effective_probabilities(ifs));
  const int burn_in = options.burn_in > 0 ? options.burn_in : default_burn_in(ifs);
  const std::uint64_t chunks = detail::chunk_count(count);
  parallel_for(chunks, options.threads, [&](std::size_t chunk, int) {
    options.cancel.check("chaos game");
    const std::uint64_t n = detail::chunk_size(count, chunk);
    // Lanes interleave step by step, so point i of the chunk is lane i % kLanes.
    std::size_t next = chunk * detail::kChunkPoints;
    detail::run_chunk(maps, pick, options.seed, chunk, n, burn_in,
                      [&](int, double x, double y, std::uint32_t map) {
                        out[next++] = Sample{{x, y}, map};
                      });
  });
  return out;
}

}  // namespace ifsfx
