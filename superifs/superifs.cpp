// SPDX-License-Identifier: Apache-2.0
#include "superifs/superifs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/steal_map.h"

namespace ifsfx {

double SuperIfs::contraction() const {
  double s = 0;
  for (const auto& f : ifs) s = std::max(s, f.contraction());
  return s;
}

void validate(const SuperIfs& super, const std::string& where) {
  auto fail = [&](const std::string& what) {
    throw Error(ErrorKind::invalid_ifs, fmt::format("{}: {}", where, what));
  };
  if (super.ifs.empty()) fail("a superIFS needs at least one IFS (got 0)");
  const std::size_t m = super.maps();
  for (std::size_t n = 0; n < super.size(); ++n) {
    const Ifs& f = super.ifs[n];
    validate(f, fmt::format("{}: IFS {}", where, n + 1));
    if (f.size() != m)
      fail(fmt::format("IFS {}: every IFS needs the same number of maps as IFS 1 (got {} for {})",
                       n + 1, f.size(), m));
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!f.maps[i].inverse())
        fail(
            fmt::format("IFS {} map {}: must be invertible, the V-variable raster inverts every "
                        "map (got det {:.3g})",
                        n + 1, i + 1, f.maps[i].det()));
    }
  }
  if (!super.probabilities.empty()) {
    if (super.probabilities.size() != super.size())
      fail(fmt::format("probabilities: one per IFS is needed (got {} for {} IFSs)",
                       super.probabilities.size(), super.size()));
    double sum = 0;
    for (std::size_t n = 0; n < super.probabilities.size(); ++n) {
      const double p = super.probabilities[n];
      if (!std::isfinite(p) || p < 0)
        fail(fmt::format("IFS {}: probability must be a finite number ≥ 0 (got {})", n + 1, p));
      sum += p;
    }
    if (!(sum > 0)) fail("probabilities: they must not all be zero (got sum 0)");
  }
  if (!super.colouring.empty()) {
    if (super.colouring.size() != 1 && super.colouring.size() != super.size())
      fail(fmt::format("colouring: give one IFS for all or one per IFS (got {} for {} IFSs)",
                       super.colouring.size(), super.size()));
    for (std::size_t n = 0; n < super.colouring.size(); ++n) {
      const Ifs& g = super.colouring[n];
      // Tilings by maps of factor 1 that contract in pairs (the strip tilings) are good colourings.
      validate(g, fmt::format("{}: colouring {}", where, n + 1), {.allow_expansive = true});
      if (g.size() != m)
        fail(fmt::format("colouring {}: needs as many maps as the IFSs (got {} for {})", n + 1,
                         g.size(), m));
    }
  }
  if (super.view) {
    const Box& b = *super.view;
    if (!(std::isfinite(b.x0) && std::isfinite(b.x1) && std::isfinite(b.y0) &&
          std::isfinite(b.y1) && b.x1 > b.x0 && b.y1 > b.y0))
      fail(fmt::format("view: must be x0, y0, x1, y1 with x0 < x1 and y0 < y1 (got {}, {}, {}, {})",
                       b.x0, b.y0, b.x1, b.y1));
  }
}

std::vector<double> effective_probabilities(const SuperIfs& super) {
  std::vector<double> p = super.probabilities;
  if (p.empty()) p.assign(super.size(), 1.0);
  double sum = 0;
  for (double x : p) sum += x;
  for (auto& x : p) x /= sum;
  return p;
}

Ifs colouring_ifs(const SuperIfs& super, std::size_t n) {
  if (super.colouring.empty()) return default_colouring(super.maps());
  return super.colouring.size() == 1 ? super.colouring[0] : super.colouring.at(n);
}

double colouring_contraction(const SuperIfs& super) {
  // Per step, from the words of length 2: the default strip tilings (x, y) ↦ (y, (x + k)/M) have
  // factor 1 alone but 1/M in pairs, i.e. 1/√M a step.
  double s = 0;
  for (std::size_t n = 0; n < super.size(); ++n) {
    const Ifs g = colouring_ifs(super, n);
    for (const auto& a : g.maps)
      for (const auto& b : g.maps) s = std::max(s, std::sqrt(a.compose(b).contraction()));
  }
  return s;
}

Ifs union_ifs(const SuperIfs& super) {
  Ifs all;
  all.name = super.name;
  for (const auto& f : super.ifs) all.maps.insert(all.maps.end(), f.maps.begin(), f.maps.end());
  return all;
}

Box buffer_view(const SuperIfs& super, cv::Size size, const Sampling& sampling) {
  if (sampling.view) return *sampling.view;
  if (super.view) return *super.view;
  return fit_view(attractor_bounds(union_ifs(super)), size, sampling.margin);
}

int default_steps(const SuperIfs& super, cv::Size size) {
  const double s = super.contraction();
  const double pixels = std::max(size.width, size.height);
  if (!(s > 0)) return 1;
  // s^k · pixels < 1/8  ⇔  k > log(8 · pixels) / −log(s). An eighth rather than one pixel: the
  // conservative lookup adds up to a pixel or two a step, and that margin must decay as well
  // before two different starts give the same raster (buffers_test burn_in_forgets_...).
  const double k = std::floor(std::log(8 * pixels) / -std::log(s)) + 1;
  return static_cast<int>(std::clamp(k, 1.0, 500.0));
}

}  // namespace ifsfx
