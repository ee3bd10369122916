// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "collage/map_params.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

CmaesOptions cmaes_options(const AttractorRefineOptions& options) {
  CmaesOptions cmaes;
  cmaes.sigma = options.sigma;
  cmaes.max_evaluations = options.max_evaluations;
  cmaes.deadline = options.deadline;
  cmaes.seed = options.seed;
  cmaes.threads = options.threads;
  cmaes.progress = options.progress;
  cmaes.cancel = options.cancel;
  return cmaes;
}

}  // namespace

AttractorRefined refine_on_attractor(const AttractorLoss& loss, std::span<const AffineMap> start,
                                     const AttractorRefineOptions& options) {
  MapCoordinates frame{options.centre, options.max_factor, {}};
  const std::vector<double> x0 = to_coordinates(start, frame);
  const CmaesOptions cmaes = cmaes_options(options);
  const CmaesResult found = minimise_cmaes(
      [&](std::span<const double> x) { return loss(from_coordinates(x, frame)); }, x0, cmaes);
  return {from_coordinates(found.x, frame), found.value, found.evaluations, found.deadline_reached};
}

AttractorRefined refine_map_on_attractor(const AttractorLoss& loss, std::span<const AffineMap> maps,
                                         std::size_t index, const AttractorRefineOptions& options) {
  if (index >= maps.size())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("refine one map: index must be below the map count {} (got {})",
                            maps.size(), index));
  MapCoordinates frame{options.centre, options.max_factor, {}};
  const std::vector<double> all = to_coordinates(maps, frame);
  const auto first = static_cast<std::ptrdiff_t>(6 * index);
  const std::vector<double> x0(all.begin() + first, all.begin() + first + 6);
  // The maps of `all` with maps[index]'s coordinates replaced by `x`.
  const auto with = [&](std::span<const double> x) {
    std::vector<double> y = all;
    std::copy(x.begin(), x.end(), y.begin() + first);
    return from_coordinates(y, frame);
  };
  const CmaesOptions cmaes = cmaes_options(options);
  const CmaesResult found =
      minimise_cmaes([&](std::span<const double> x) { return loss(with(x)); }, x0, cmaes);
  return {with(found.x), found.value, found.evaluations, found.deadline_reached};
}

std::vector<AffineMap> perturbed(std::span<const AffineMap> maps, Point centre, double max_factor,
                                 double scale, Rng& rng) {
  MapCoordinates frame{centre, max_factor, {}};
  std::vector<double> x = to_coordinates(maps, frame);
  for (double& v : x) {
    // Box–Muller: one normal draw from two uniform ones.
    const double u1 = 1 - rng.uniform(), u2 = rng.uniform();
    v += scale * std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
  }
  return from_coordinates(x, frame);
}

bool metropolis_accepts(double delta, double temperature, double u) {
  if (delta <= 0) return true;
  if (!(temperature > 0)) return false;
  return u < std::exp(-delta / temperature);
}

}  // namespace ifsfx::collage
