// SPDX-License-Identifier: Apache-2.0
// Contractive coordinates for affine maps (issue 32): every point of the coordinate space is a map
// that contracts, so an optimiser moving all maps at once never proposes one that does not.
//
// A map is written by its singular value decomposition about a fixed centre c (L's centroid),
//   f(x) = R(θ) · diag(σ₁, ±σ₂) · R(φ) · (x − c) + t,
// with rotations R, the sign a reflection flag (kept fixed: it cannot change continuously), and
// σ_k = max_factor · logistic(u_k) ∈ (0, max_factor): the contraction max(σ₁, σ₂) stays below
// max_factor whatever u is. t is where f sends c, so moving the linear part leaves the piece in
// place. The six coordinates of a map are (θ, φ, u₁, u₂, t_x / kTranslationUnit, t_y / …).
#pragma once

#include <span>
#include <vector>

#include "ifs/affine_map.h"

namespace ifsfx::collage {

// Plane units per coordinate of t: a step of 0.1 in every coordinate moves a map comparably.
inline constexpr double kTranslationUnit = 0.1;

struct MapCoordinates {
  Point centre;                 // c
  double max_factor = 0.97;     // the bound on σ₁, σ₂
  std::vector<bool> reflected;  // per map: the sign of det f
};

// The coordinates of `maps` (6 per map) and, in `frame.reflected`, their reflection flags.
// Singular values are clamped into [1e-3, 0.999] · max_factor first, so a map that does not
// contract (or is singular) comes back as the nearest one that does.
std::vector<double> to_coordinates(std::span<const AffineMap> maps, MapCoordinates& frame);

// The maps of coordinates `x` (6 per map) in `frame`.
std::vector<AffineMap> from_coordinates(std::span<const double> x, const MapCoordinates& frame);

}  // namespace ifsfx::collage
