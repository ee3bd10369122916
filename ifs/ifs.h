// SPDX-License-Identifier: Apache-2.0
// An iterated function system {X; f1..fN; p1..pN} (paper §2, eq. 1–2; docs/design.md §1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ifs/affine_map.h"

namespace ifsfx {

// The largest plane coordinate the geometry works with: an attractor (and a view) must lie within
// ±kMaxCoordinate, so that its extent, its squares and its pixel scale stay finite and exact
// enough in double precision. validate() refuses IFSs whose attractor would reach beyond it.
inline constexpr double kMaxCoordinate = 1e100;

// An RGB colour, components in [0, 1].
struct Rgb {
  double r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Ifs {
  std::string name;
  std::vector<AffineMap> maps;
  // One per map, summing to 1 once normalised; empty means "default" (see default_probabilities).
  std::vector<double> probabilities;
  // Optional colour per map (measure and tops palettes); empty means "use the palette".
  std::vector<Rgb> colours;

  std::size_t size() const { return maps.size(); }

  // Contraction factor of the IFS: the largest factor of its maps (paper §2).
  double contraction() const;

  friend bool operator==(const Ifs&, const Ifs&) = default;
};

// Probabilities ∝ |det f_n| with a floor, so that a degenerate map (det 0, e.g. the fern's stem)
// is still visited: p_n = max(|det|, floor · max|det|) normalised (docs/design.md §1).
std::vector<double> default_probabilities(const std::vector<AffineMap>& maps, double floor = 0.01);

// The probabilities to iterate with: the given ones normalised to sum 1, or the defaults.
std::vector<double> effective_probabilities(const Ifs& ifs);

struct ValidateOptions {
  // Accept maps with factor ≥ 1 provided the IFS contracts on average (mean_log_contraction < 0).
  bool allow_expansive = false;
  // false: check only what a chaos game needs to run at all (the checks below but contraction).
  bool require_contraction = true;
};

// Checks an IFS before use and throws Error{invalid_ifs} naming the culprit: no maps, a NaN/inf
// coefficient or one beyond ±kMaxCoordinate, an attractor that would reach beyond
// ±kMaxCoordinate (a contractive IFS's lies within max_n |f_n(c) − c| / (1 − s) of the fixed
// point c of its first map), probabilities of the wrong count, negative, non-finite or all zero,
// colours of the wrong count, a map with factor ≥ 1 (unless allowed, and then an IFS that does
// not contract on average). `where` prefixes messages (a file name, a preset name).
void validate(const Ifs& ifs, const std::string& where, const ValidateOptions& options = {});

// The mean log contraction of the IFS per step, min over word lengths k = 1..3 of
// Σ_w p_w log ‖f_w‖ / k (the IFS contracts on average when it is < 0).
double mean_log_contraction(const Ifs& ifs);

}  // namespace ifsfx
