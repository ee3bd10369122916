// SPDX-License-Identifier: Apache-2.0
#include "ifs/ifs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx {

double Ifs::contraction() const {
  double s = 0;
  for (const auto& m : maps) s = std::max(s, m.contraction());
  return s;
}

std::vector<double> default_probabilities(const std::vector<AffineMap>& maps, double floor) {
  std::vector<double> p(maps.size());
  double largest = 0;
  for (const auto& m : maps) largest = std::max(largest, std::abs(m.det()));
  if (largest == 0) largest = 1;  // all maps degenerate: uniform
  double sum = 0;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    p[i] = std::max(std::abs(maps[i].det()), floor * largest);
    sum += p[i];
  }
  for (auto& x : p) x /= sum;
  return p;
}

std::vector<double> effective_probabilities(const Ifs& ifs) {
  if (ifs.probabilities.empty()) return default_probabilities(ifs.maps);
  std::vector<double> p = ifs.probabilities;
  double sum = 0;
  for (double x : p) sum += x;
  for (auto& x : p) x /= sum;
  return p;
}

void validate(const Ifs& ifs, const std::string& where, const ValidateOptions& options) {
  auto fail = [&](const std::string& what) {
    throw Error(ErrorKind::invalid_ifs, fmt::format("{}: {}", where, what));
  };
  if (ifs.maps.empty()) fail("an IFS needs at least one map (got 0)");
  for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
    if (!ifs.maps[i].finite())
      fail(fmt::format("map {}: coefficients must be finite numbers (got NaN or inf)", i + 1));
    for (const double k : ifs.maps[i].coefficients())
      if (std::abs(k) > kMaxCoordinate)
        fail(fmt::format("map {}: coefficients must lie within ±{:g} (got {:g})", i + 1,
                         kMaxCoordinate, k));
  }
  if (!ifs.probabilities.empty()) {
    if (ifs.probabilities.size() != ifs.maps.size())
      fail(fmt::format("probabilities: one per map is needed (got {} for {} maps)",
                       ifs.probabilities.size(), ifs.maps.size()));
    double sum = 0;
    for (std::size_t i = 0; i < ifs.probabilities.size(); ++i) {
      const double p = ifs.probabilities[i];
      if (!std::isfinite(p) || p < 0)
        fail(fmt::format("map {}: probability must be a finite number ≥ 0 (got {})", i + 1, p));
      sum += p;
    }
    if (!(sum > 0)) fail("probabilities: they must not all be zero (got sum 0)");
  }
  if (!ifs.colours.empty() && ifs.colours.size() != ifs.maps.size())
    fail(fmt::format("colours: one per map is needed (got {} for {} maps)", ifs.colours.size(),
                     ifs.maps.size()));
  if (!options.require_contraction) return;
  for (std::size_t i = 0; i < ifs.maps.size(); ++i) {
    const double s = ifs.maps[i].contraction();
    if (s >= 1 && !options.allow_expansive)
      fail(
          fmt::format("map {}: contraction factor must be < 1 (got {:.4g}); "
                      "allow_expansive accepts it if the IFS contracts on average",
                      i + 1, s));
  }
  // Where the attractor reaches: within max_n |f_n(c) − c| / (1 − s) of any point c (here the
  // fixed point of the first map). Beyond ±kMaxCoordinate its framing and rasters overflow.
  if (const double s = ifs.contraction(); s < 1) {
    Point c{0, 0};
    const AffineMap& f0 = ifs.maps[0];
    if (auto inv = AffineMap{1 - f0.a, -f0.b, -f0.c, 1 - f0.d, 0, 0}.inverse())
      c = (*inv)({f0.e, f0.f});
    double reach = 0;
    for (const auto& f : ifs.maps) {
      const Point q = f(c);
      reach = std::max(reach, std::hypot(q.x - c.x, q.y - c.y));
    }
    const double far = std::max(std::abs(c.x), std::abs(c.y)) + reach / (1 - s);
    if (!(far <= kMaxCoordinate))
      fail(
          fmt::format("the attractor would reach {:.3g} from the origin, beyond ±{:g}: its "
                      "translations are too large for its factors (scale the IFS down)",
                      far, kMaxCoordinate));
  }
  if (options.allow_expansive) {
    const double rate = mean_log_contraction(ifs);
    if (!(rate < 0))
      fail(
          fmt::format("the IFS must contract on average: the mean log factor of its map "
                      "compositions must be < 0 (got {:.4g})",
                      rate));
  }
}

double mean_log_contraction(const Ifs& ifs) {
  // Σ over words w of length k of p_w · log ‖f_w‖ / k estimates the top Lyapunov exponent from
  // above; any k with a negative value proves contraction on average. Words of length 2 and 3
  // catch maps that only contract once composed, such as the "swap" tilings (x, y) ↦ (y, (x+k)/N).
  const auto p = effective_probabilities(ifs);
  const std::size_t n = ifs.maps.size();
  double best = 0;
  bool first = true;
  std::vector<std::pair<AffineMap, double>> words{{AffineMap{}, 1.0}};
  for (int k = 1; k <= 3; ++k) {
    if (words.size() * n > 100000) break;  // large IFSs: keep the cost bounded
    std::vector<std::pair<AffineMap, double>> longer;
    longer.reserve(words.size() * n);
    double sum = 0;
    for (const auto& [w, pw] : words)
      for (std::size_t i = 0; i < n; ++i) {
        const AffineMap composed = w.compose(ifs.maps[i]);
        const double pi = pw * p[i];
        if (pi > 0) sum += pi * std::log(std::max(composed.contraction(), 1e-300));
        longer.emplace_back(composed, pi);
      }
    const double rate = sum / k;
    best = first ? rate : std::min(best, rate);
    first = false;
    words = std::move(longer);
  }
  return best;
}

}  // namespace ifsfx
