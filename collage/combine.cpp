// SPDX-License-Identifier: Apache-2.0
#include "collage/combine.h"

#include <algorithm>
#include <array>
#include <optional>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

namespace {

constexpr int kMaxMoves = 64;  // per map and sweep: a map sliding a long way waits for the next

// The objective of `fixed` (merged footprints of the maps kept, or none) with `part` added.
double value_with(const CollageObjective& objective, const Footprint* fixed,
                  const Footprint& part) {
  const Footprint* parts[] = {fixed, &part};
  return objective.terms(std::span<const Footprint* const>(parts + (fixed ? 0 : 1), parts + 2))
      .value;
}

// The merged footprint of the chosen maps but the one in `skip` (none: all of them); nothing
// when no map is left.
std::optional<Footprint> merged(std::span<const Footprint> pool,
                                const std::vector<std::size_t>& chosen, std::size_t skip) {
  std::vector<const Footprint*> parts;
  for (std::size_t slot = 0; slot < chosen.size(); ++slot)
    if (slot != skip) parts.push_back(&pool[chosen[slot]]);
  if (parts.empty()) return std::nullopt;
  return merge(parts);
}

}  // namespace

std::vector<std::size_t> select_maps(const CollageObjective& objective,
                                     std::span<const Footprint> pool, int n,
                                     const SelectOptions& options) {
  if (n < 1 || std::ssize(pool) < n)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("select: {} maps cannot be chosen from a pool of {}", n, pool.size()));
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  Rng rng(stream_seed(options.seed, 0x73656c656374ULL));
  std::vector<std::size_t> chosen;
  std::vector<char> taken(pool.size(), 0);
  while (std::ssize(chosen) < n) {
    // Every addition, best first (ties: the lower index).
    const auto fixed = merged(pool, chosen, none);
    std::vector<std::pair<double, std::size_t>> additions;
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (!taken[i])
        additions.emplace_back(value_with(objective, fixed ? &*fixed : nullptr, pool[i]), i);
    std::sort(additions.begin(), additions.end());
    const auto choices =
        std::min<std::size_t>(additions.size(), static_cast<std::size_t>(options.spread) + 1);
    const std::size_t pick = choices > 1
                                 ? additions[rng.below(static_cast<std::uint32_t>(choices))].second
                                 : additions.front().second;
    chosen.push_back(pick);
    taken[pick] = 1;
  }

  // Single swaps: each slot's map against every unchosen one, the others merged once.
  for (int sweep = 0; sweep < options.swap_sweeps; ++sweep) {
    bool changed = false;
    for (std::size_t slot = 0; slot < chosen.size(); ++slot) {
      options.cancel.check("fit");
      if (std::chrono::steady_clock::now() >= options.deadline) return chosen;
      const auto others = merged(pool, chosen, slot);
      const Footprint* fixed = others ? &*others : nullptr;
      std::size_t best = chosen[slot];
      double best_value = value_with(objective, fixed, pool[best]);
      for (std::size_t i = 0; i < pool.size(); ++i) {
        if (taken[i]) continue;
        const double v = value_with(objective, fixed, pool[i]);
        if (v < best_value) best_value = v, best = i;
      }
      if (best != chosen[slot]) {
        taken[chosen[slot]] = 0;
        taken[best] = 1;
        chosen[slot] = best;
        changed = true;
      }
    }
    if (!changed) break;
  }
  return chosen;
}

namespace {

// Compass search one map at a time. `begin(k)` is called before map k's turn; `score(k, f, d)`
// is the criterion with map k replaced by f (d: the move's slot 0..11, for per-move scratch);
// `accept(k, d)` is told which move was taken.
template <typename Begin, typename Score, typename Accept>
DescentResult compass(std::vector<AffineMap> maps, double value, Point mu, double pixel,
                      const DescentOptions& options, Begin&& begin, Score&& score,
                      Accept&& accept) {
  DescentResult result;
  std::array<AffineMap, 12> moves;
  std::array<double, 12> move_values;
  bool stop = false;  // the deadline came or the evaluations are spent
  for (int sweep = 0; sweep < options.sweeps && !stop; ++sweep) {
    for (std::size_t k = 0; k < maps.size(); ++k) {
      begin(k);
      std::array<double, 6> step = {options.linear_step,        options.linear_step,
                                    options.linear_step,        options.linear_step,
                                    options.pixel_step * pixel, options.pixel_step * pixel};
      for (int halvings = 0, moved = 0; halvings <= options.halvings && moved < kMaxMoves;) {
        options.cancel.check("fit");
        if (options.max_evaluations > 0 && result.evaluations + 12 > options.max_evaluations) {
          stop = true;
          break;
        }
        if (std::chrono::steady_clock::now() >= options.deadline) {
          result.deadline_reached = stop = true;
          break;
        }
        // Moves about L's centroid μ: the linear part changes with f(μ) kept, so that turning
        // or stretching a piece does not also shove it away (as moving a..d at the origin
        // would).
        for (std::size_t d = 0; d < 12; ++d) {
          auto c = maps[k].coefficients();
          const double delta = (d % 2 ? -1 : 1) * step[d / 2];
          c[d / 2] += delta;
          if (d / 2 == 0) c[4] -= delta * mu.x;  // a: e keeps f(μ)
          if (d / 2 == 1) c[4] -= delta * mu.y;  // b
          if (d / 2 == 2) c[5] -= delta * mu.x;  // c: f keeps f(μ)
          if (d / 2 == 3) c[5] -= delta * mu.y;  // d
          moves[d] = AffineMap::from_coefficients(c);
        }
        parallel_for(12, options.threads,
                     [&](std::size_t d, int) { move_values[d] = score(k, moves[d], d); });
        result.evaluations += 12;
        std::size_t best = 12;
        double best_value = value;
        for (std::size_t d = 0; d < 12; ++d)
          if (move_values[d] < best_value) best_value = move_values[d], best = d;
        if (best < 12) {
          maps[k] = moves[best];
          accept(k, best);
          value = best_value;
          ++moved;
        } else {
          for (auto& s : step) s *= 0.5;
          ++halvings;
        }
      }
      if (stop) break;
    }
  }
  result.maps = std::move(maps);
  result.value = value;
  return result;
}

}  // namespace

DescentResult descend_each_map(const CollageObjective& objective, std::vector<AffineMap> maps,
                               const DescentOptions& options) {
  if (maps.empty())
    throw Error(ErrorKind::invalid_argument, "descend: at least one map is needed (got 0)");
  if (options.iterations < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("descend: iterations must be ≥ 1 (got {})", options.iterations));
  const double pixel = 1.0 / objective.size();
  if (options.iterations > 1) {
    // Every move maps all of W^k(L) again: nothing to keep between moves.
    std::array<std::vector<AffineMap>, 12> trials;
    const double start = objective.iterated(maps, options.iterations);
    return compass(
        maps, start, objective.centroid(), pixel, options, [](std::size_t) {},
        [&](std::size_t k, const AffineMap& f, std::size_t d) {
          trials[d] = maps;  // the maps before this step: compass replaces only map k
          trials[d][k] = f;
          return objective.iterated(trials[d], options.iterations);
        },
        [&](std::size_t k, std::size_t d) { maps[k] = trials[d][k]; });
  }
  // One step of W: the other maps' footprints are merged once per turn, a move costs one
  // footprint.
  std::vector<Footprint> parts;
  for (const auto& f : maps) parts.push_back(objective.footprint(f));
  std::vector<const Footprint*> pointers;
  for (const auto& p : parts) pointers.push_back(&p);
  const double start = objective.terms(std::span<const Footprint* const>(pointers)).value;
  std::optional<Footprint> others;
  std::array<Footprint, 12> move_parts;
  return compass(
      maps, start, objective.centroid(), pixel, options,
      [&](std::size_t k) {
        std::vector<const Footprint*> rest = pointers;
        rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(k));
        others = rest.empty() ? std::nullopt : std::optional<Footprint>(merge(rest));
      },
      [&](std::size_t, const AffineMap& f, std::size_t d) {
        move_parts[d] = objective.footprint(f);
        return value_with(objective, others ? &*others : nullptr, move_parts[d]);
      },
      [&](std::size_t k, std::size_t d) { parts[k] = std::move(move_parts[d]); });
}

}  // namespace ifsfx::collage
