// SPDX-License-Identifier: Apache-2.0
// A global self-similarity search (issue 32): where does the shape L hold a smaller copy of
// itself? For a true fractal the maps of its IFS are exact answers — w(L) ⊂ L, by the
// self-similarity A = ∪ w_n(A) of paper eq. 1 — and the fern's largest copy (0.85 of the whole,
// turned 2.5°) is the map a fit must find first, which a search over pieces of a partition never
// proposes (a piece is never most of L).
//
// Template matching of L against scaled, turned copies of itself: for every linear part of a
// fixed grid, A = s · R(θ) · diag(1, a) · R(φ) · F^r (a scale s, a turn θ, an anisotropy a along
// the axis φ, a reflection F = diag(1, −1)), the copy A(L) is drawn about L's centroid c and
// cross-correlated by FFT with L grown by a pixel, on a coarse raster (64²): at every translation
// t at once this gives |w(L) ∩ L| for w(x) = A (x − c) + c + t, hence the precision
// |w(L) ∩ L| / |w(L)| — 1 when the copy lies in L — and the area it covers. The kernel also
// charges what of L lies just outside the copy (a ring two pixels out), so that a copy whose edge
// is L's edge, a part of L, beats one that merely lies inside a solid region. The best few
// translations of each linear part are kept, each scale and anisotropy its share, and polished
// by a compass search on 128² and then 256², where thin parts are apart and only the true copies
// keep their points in L (similarity_polish.h); those that do are returned, largest first, one
// of each near group (non-maximum suppression over the maps). docs/design.md §6.
#pragma once

#include <chrono>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/cancel.h"

namespace ifsfx::collage {

struct SimilarityScanOptions {
  int size = 64;  // the scan's raster side R: L is cut from the target at any cover of a pixel
  // Similarities (a = 1): `scales` factors s spaced geometrically over [min_scale, max_scale],
  // `angles` turns θ over 360°, with and without reflection.
  int scales = 12;
  int angles = 48;
  double min_scale = 0.15, max_scale = 0.92;
  // Anisotropic parts: each a in `anisotropies` (0 < a < 1; a small one draws a stalk, as the
  // fern's stem is drawn), with `skews` axes φ over 180° and half the scales and the angles.
  std::vector<double> anisotropies = {0.5, 0.05};
  int skews = 4;
  // |w(L) ∩ L| / |w(L)| a copy needs on the coarse raster (L grown by a pixel there) and on the
  // fine one.
  double min_precision = 0.9;
  double fine_precision = 0.95;
  // μ: the cost of a pixel of L just outside the copy (kRing pixels from it), against one of
  // the copy in L: a copy whose edge is L's edge is a part of L.
  double ring_weight = 1;
  int peaks = 3;  // translations kept per linear part
  // The coarse copies (largest first, one of each near group) moved on a raster of side
  // fine_size (at most the target's), where thin parts are apart, by a compass search of
  // polish_evaluations steps on `samples` points of L; those whose precision there is
  // fine_precision are kept, largest first, one of each near group.
  int candidates = 1500;
  int fine_size = 256;
  int samples = 512;
  int polish_evaluations = 80;
  int keep = 512;   // copies kept in all
  int threads = 0;  // linear parts in parallel; 0 = all cores
  // No linear part starts after this time (the result then depends on the clock); the default
  // never comes.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Polled between linear parts; a stop request throws Error{interrupted}.
  CancelToken cancel;
};

// A copy of L inside L.
struct SelfCopy {
  AffineMap map;         // w, on the IFS plane of the target (working raster convention)
  double precision = 0;  // the share of L's points w moves into L, fine raster
  double area = 0;       // |det w| = |w(L)| / |L|
};

// The number of linear parts the scan tries with these options (each one correlation).
int linear_part_count(const SimilarityScanOptions& options);

// What a scan costs in the fit's evaluations (FitOptions::max_evaluations: about the time of one
// collage evaluation each): one per linear part, and one per 25000 points of the polish —
// measured, 2.4 CPU-seconds for the defaults on a 64²/256² fern, about 5300 evaluations' time.
long scan_cost(const SimilarityScanOptions& options);

// The copies of `target` (a working raster, or a finer raster of its frame) inside itself,
// largest first, at most options.keep; deterministic for any thread count (without a
// deadline). Throws Error{invalid_argument} for a target that is not a square CV_8UC1 raster,
// that vanishes at the scan's size, or for options out of range.
//   auto copies = scan_self_similarity(working_raster(load_target("fern.png")));
std::vector<SelfCopy> scan_self_similarity(const cv::Mat& target,
                                           const SimilarityScanOptions& options = {});

}  // namespace ifsfx::collage
