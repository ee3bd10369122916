// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_fit.h"

#include <cmath>
#include <numbers>

#include "collage/map_params.h"

namespace ifsfx::collage {

AttractorRefined refine_on_attractor(const AttractorLoss& loss, std::span<const AffineMap> start,
                                     const AttractorRefineOptions& options) {
  MapCoordinates frame{options.centre, options.max_factor, {}};
  const std::vector<double> x0 = to_coordinates(start, frame);
  CmaesOptions cmaes;
  cmaes.sigma = options.sigma;
  cmaes.max_evaluations = options.max_evaluations;
  cmaes.deadline = options.deadline;
  cmaes.seed = options.seed;
  cmaes.threads = options.threads;
  cmaes.progress = options.progress;
  cmaes.cancel = options.cancel;
  const CmaesResult found = minimise_cmaes(
      [&](std::span<const double> x) { return loss(from_coordinates(x, frame)); }, x0, cmaes);
  return {from_coordinates(found.x, frame), found.value, found.evaluations, found.deadline_reached};
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
