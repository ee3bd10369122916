// SPDX-License-Identifier: Apache-2.0
// A superIFS (paper §5, eq. 10–11; docs/design.md §5): N IFSs F^n = {f^n_1..f^n_M; p^n_1..p^n_M},
// each of M maps, chosen with probabilities P_1..P_N, and an optional colouring superIFS G^n =
// {g^n_1..g^n_M} on the source's unit square for colour stealing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/view.h"

namespace ifsfx {

struct SuperIfs {
  std::string name;
  // F^1..F^N, every one with the same number M of maps. Each keeps its own map probabilities
  // p^n_m (used by the measure variant; the set step of eq. 14 uses every map).
  std::vector<Ifs> ifs;
  // P_1..P_N, normalised once used; empty means uniform.
  std::vector<double> probabilities;
  // Colouring superIFS G^n on the unit square (y up): empty = default_colouring(M) for every n,
  // one entry = that IFS for every n, N entries = one per F^n.
  std::vector<Ifs> colouring;
  // The rectangle of the plane shown on the whole raster (stretched); empty = the attractor of
  // all maps together, auto-framed with the raster's aspect.
  std::optional<Box> view;

  std::size_t size() const { return ifs.size(); }                       // N
  std::size_t maps() const { return ifs.empty() ? 0 : ifs[0].size(); }  // M

  // The largest contraction factor of all maps f^n_m.
  double contraction() const;
};

// Checks a superIFS before use and throws Error{invalid_ifs} naming the culprit, in the manner of
// validate(const Ifs&): no IFS, an IFS that fails validate(), IFSs of different map counts,
// P of the wrong count, negative, non-finite or all zero, a colouring of the wrong count, and a
// singular map (det 0: the raster step inverts every map, see buffers.h). `where` prefixes the
// messages (a file name, a preset name).
void validate(const SuperIfs& super, const std::string& where);

// P_1..P_N normalised to sum 1, or uniform when none are given.
std::vector<double> effective_probabilities(const SuperIfs& super);

// The colouring IFS G^n (n from 0) with M maps, after the defaults above.
Ifs colouring_ifs(const SuperIfs& super, std::size_t n);

// The contraction per step of the colouring IFSs G^1..G^N: the largest √factor of their words of
// length 2 (a strip tiling's maps have factor 1 alone, 1/M in pairs).
double colouring_contraction(const SuperIfs& super);

// Every map of every F^n as one IFS: its attractor holds every V-variable fractal of the superIFS,
// so a view that frames it frames all of them.
Ifs union_ifs(const SuperIfs& super);

// The plane rectangle the buffers live on for a raster of `size`: sampling.view when given, else
// super.view when given, else the bounds of union_ifs(super) fitted to the raster's aspect with
// sampling.margin on every side.
Box buffer_view(const SuperIfs& super, cv::Size size, const Sampling& sampling = {});

// Steps after which any starting buffer has converged to the V-variable family on a raster of
// `size`: the least k with s^k · max(W, H) < 1/8 pixel for the largest factor s (below a pixel,
// with room for the conservative raster's margin to decay too), capped at 500.
int default_steps(const SuperIfs& super, cv::Size size);

}  // namespace ifsfx
