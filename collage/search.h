// SPDX-License-Identifier: Apache-2.0
// The range/domain search of fractal image compression (Jacquin 1992; Fisher, "Fractal Image
// Compression", 1995), turned to shapes: the starting maps of the collage fit (paper §7: the maps
// "can also be found by fractal image compression methods").
//
// The ranges are the N pieces of a partition of L (initialise.h); the domain is the whole of L.
// For each piece P, a discretised family of affine maps f(x) = R(θ) F diag(sx, sy) K (x − μ_L)
// + μ_P — rotations θ, a reflection F, independent scales sx, sy and a shear K — is scored by
// P's share of the collage objective, sums of lookups in the distance transforms of L and P
// (a point is in a set where the distance is 0):
//   score(f) = [ |P \ f(L)| + |f(L) \ L| + w |f(L) ∩ (L \ P)| ] / |P|
//            + 0.05 · ( mean_{p ∈ L} d(f(p), L) + mean_{q ∈ P} √|det f| · d(f⁻¹(q), L) )
// The first part is the area f(L) gets wrong, as a fraction of the piece: the piece it misses
// (q ∈ f(L) exactly when f⁻¹(q) ∈ L), what leaves L, and, weighted by w, what lands on other
// pieces; the second, in pixels, is the piece's share of the collage distance (paper eq. 3) —
// how far f(L) strays from L, and how far the piece lies from f(L), since d(q, f(L)) ≈
// √|det f| · d(f⁻¹(q), L) — which keeps the score telling near misses from far ones. Every map
// sends L's centroid to P's (an affine image of L has its centroid at f(μ_L)). The best coarse
// candidates are polished by a compass search over (θ, sx, sy, k, translation), and the best few
// distinct ones per piece are kept for the fit to combine (combine.h).
#pragma once

#include <chrono>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/cancel.h"

namespace ifsfx::collage {

struct SearchOptions {
  int angles = 32;  // rotations θ tried per piece, evenly spaced over 360° (≥ 1)
  // sx, sy = √(|P| / |L|) · 2^(i/2) for i = −steps..steps, with sx·sy within 4× of |P| / |L|
  int scale_steps = 5;
  int shears = 3;             // shear factors evenly spaced in [−0.5, 0.5] (1: none)
  int samples = 128;          // points of L and of P that score a coarse candidate
  int polish_samples = 600;   // ... and a polished one
  int polished = 8;           // coarse winners polished per piece
  int keep = 4;               // distinct polished candidates kept per piece
  double piece_weight = 0.5;  // w: spilling onto other pieces, relative to leaving L
  double max_factor = 0.95;   // candidates whose contraction reaches this are not tried
  int threads = 0;            // pieces are searched in parallel; 0 = all cores
  // No further angle and no further polish starts at or after this time (every piece scans one
  // angle at least); what was found by then is kept. The default never comes.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  // Polled between pieces, angles and polishing steps; a stop request throws Error{interrupted}.
  CancelToken cancel;
};

// One map L → piece and its score (pixels, lower is better).
struct Candidate {
  AffineMap map;  // on the IFS plane (working raster convention, target.h)
  double score = 0;
};

// For each piece k = 0..n−1 of `labels` (CV_32SC1, −1 outside L, as partition() returns), the
// best distinct maps from L onto it, best first (at most `keep`). An empty piece gets one small
// copy of L at L's centroid. The result depends on the inputs only, not on the thread count.
//   auto found = search_pieces(raster, partition(raster, 6, {.by_component = true}), 6);
std::vector<std::vector<Candidate>> search_pieces(const cv::Mat& target, const cv::Mat& labels,
                                                  int n, const SearchOptions& options = {});

// The score above for one map and one piece (a CV_8UC1 mask inside `target`), on up to `samples`
// points of each: what search_pieces ranks by, exposed for tests.
double piece_score(const cv::Mat& target, const cv::Mat& piece, const AffineMap& f,
                   int samples = 1200, double piece_weight = 0.5);

}  // namespace ifsfx::collage
