// SPDX-License-Identifier: Apache-2.0
// Collage-theorem fitting (paper §2, eq. 3; docs/design.md §6): search N affine maps whose collage
// W(L) = ∪ f_n(L) covers the target L tightly with a small contraction s, then report what the
// collage theorem promises and what the rendered attractor A actually achieves:
//   h(L, W(L)) / (1 + s)  ≤  h(L, A)  ≤  h(L, W(L)) / (1 − s).
//
// Targets are working rasters (target.h): L is the set of pixel centres of an S×S mask on the
// unit square of the IFS plane, y up; distances are in plane units (the square's side is 1).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "collage/collage.h"
#include "collage/search.h"
#include "ifs/cancel.h"
#include "ifs/ifs.h"

namespace ifsfx::collage {

// How much of one connected component (8-connected) of L the attractor covers: a part of a
// multi-part shape too small for a map of its own may be left out.
struct PartCoverage {
  int area = 0;        // pixels of the working raster
  Point centre;        // its centroid, IFS plane
  double covered = 0;  // fraction of its pixels that A hits
};

// What the collage theorem says about an IFS against a target, and what its attractor does.
struct CollageReport {
  double collage_distance = 0;  // h(L, W(L)), plane units, never below the exact value
  double contraction = 0;       // s, the largest factor of the maps
  double lower_bound = 0;       // h(L, W(L)) / (1 + s) ≤ h(L, A)
  double upper_bound = 0;       // h(L, A) ≤ h(L, W(L)) / (1 − s); +inf when s ≥ 1
  double hausdorff = 0;         // h(L, A) measured on the raster: L against the pixels A hits
  // How far the measured h(L, A) may lie from the true one: the centre of a pixel that A hits is
  // within half a pixel diagonal (√2 / 2S) of A, and a fully rendered A is within that of the
  // centres; so the collage theorem promises hausdorff ≤ upper_bound + raster_error.
  double raster_error = 0;
  double iou = 0;          // |L ∩ A| / |L ∪ A| on the raster (A outside the square counts)
  double collage_iou = 0;  // |L ∩ W(L)| / |L ∪ W(L)| on the raster
  // IoU(L, A) on a finer raster of the target's frame (FitOptions::fine_target, e.g. 4S): thin
  // parts and holes that the working raster blurs show here. 0 when no fine raster was given.
  double fine_iou = 0;
  int fine_size = 0;     // that raster's side; 0 when none
  double pixel = 0;      // the raster's pixel size in plane units, 1/S
  bool clipped = false;  // A reaches beyond the measuring canvas (the square grown by 1 each way)
  cv::Mat collage;       // W(L) on the working raster, CV_8UC1 0/255
  cv::Mat attractor;     // A on the working raster, CV_8UC1 0/255
  std::vector<PartCoverage> parts;  // L's components, largest first

  // The collage theorem's bound holds for what was measured (within the raster's error).
  bool bound_holds() const { return hausdorff <= upper_bound + raster_error; }
};

struct AssessOptions {
  double quality = 256;  // chaos-game points per pixel when rendering A
  std::uint64_t seed = 1;
  int threads = 0;  // 0 = all cores
};

// The collage report of `ifs` against `target` (a working raster). The IFS must be contractive
// for the bounds to mean anything; its attractor is rendered on the target's grid, extended
// where A leaves the unit square.
//   auto r = assess(raster, sierpinski);  // r.collage_distance ≈ √3/12 for a filled triangle
CollageReport assess(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options = {});

// What the fit optimises after its start.
enum class FitMethod {
  // Issue 32: the attractor itself. The collage stages below run on 40% of the budget; then
  // the best attractor so far, covers of L by copies of itself (similarity_scan.h,
  // similarity_cover.h; aligned by ICP on fine_target), the maps searched on a cut partition
  // (cut_partition.h) and the best distinct runs are refined by CMA-ES on the attractor loss
  // (attractor_loss.h) over all maps at once, coarse to fine (32², 64², the working raster; cut
  // from fine_target when given), with perturb-and-accept escapes between (attractor_fit.h) and
  // ICP last (on the working raster and on fine_target); then the maps that pay least are
  // re-seeded on the regions of L that A misses (reseed.h, reseed_share); with fine_target, every
  // candidate is judged on it too, and its best is moved by CMA-ES on the loss cut at its size
  // last. Optionally (grow_share, off by default: no gain measured) the escapes' best is grown
  // again from N − 2 maps onto the regions A misses (grow.h) before the working raster's stage.
  attractor,
  // Issues 14–15: the collage objective W(L) against L, then a polish on W^k(L); the attractor
  // is only rendered to choose between candidates.
  collage,
};

// IoU(L, A) alone, A rendered as assess() renders it: what CollageReport::fine_iou measures on a
// finer raster of the target's frame. Throws as assess() does.
double attractor_iou(const cv::Mat& target, const Ifs& ifs, const AssessOptions& options = {});

// Where the starting maps come from.
enum class Initialisation {
  // Issue 14's: split L along principal axes (restarts: k-means++ splits) and match each part's
  // first and second moments with one of 16 orthogonal turns (initialise.h).
  moments,
  // The range/domain search of fractal image compression (search.h) on several partitions of L
  // (one part per connected component at least); N of the maps found are chosen (combine.h),
  // the next-best choices and kicks of the best tried while the budget lasts.
  search,
};

enum class FitPhase {
  partition,  // splitting L into the N ranges
  search,     // searching maps L → range and choosing N of them
  refine,     // descents, CMA-ES and ICP on the collage objective, the polish on W^k(L)
  attractor,  // CMA-ES and escapes on the attractor loss (FitMethod::attractor)
};
const char* to_string(FitPhase phase) noexcept;

struct FitProgress {
  FitPhase phase = FitPhase::partition;
  int run = 0;           // 0-based
  int runs = 0;          // moments: runs planned; search: restarts + 1 (kicks run on after them)
  long evaluations = 0;  // objective evaluations so far, all runs
  double objective = 0;  // best value of this run so far (phase attractor: the attractor loss)
  double best = 0;       // best value of all runs so far
  double best_iou = 0;   // IoU(L, A) of the best IFS so far; 0 until the first is rendered
  double seconds = 0;    // since the fit started
};

struct FitOptions {
  int maps = 4;  // N, 1..32
  std::uint64_t seed = 1;
  Initialisation init = Initialisation::search;
  // Initialisation::search only: with moments the fit is issue 14's, whatever the method.
  FitMethod method = FitMethod::attractor;
  // FitMethod::attractor: the distinct starts taken from the collage search's runs.
  int starts = 3;
  // FitMethod::attractor: further starts from the self-similarity scan (similarity_scan.h): the
  // copies of L inside itself, N of them chosen by greedy set cover (similarity_cover.h), this
  // many distinct covers. It costs a fixed number of evaluations (scan_cost, about 5300: 2% of
  // the default budget) and is skipped when that is over a tenth of max_evaluations. 0 = none.
  int similarity_starts = 2;
  // FitMethod::attractor: the share of the attractor's stages given to re-seeding maps where the
  // error is (reseed.h, issue 32 item 3), at the start of the fine raster's stage (what it leaves
  // goes to that stage; without fine_target, the end of the working raster's); 0..0.15, 0 = none.
  double reseed_share = 0.15;
  // FitMethod::attractor: the share of the attractor's stages given to growing from fewer maps
  // (grow.h, issue 32 item 3), taken from the end of the escapes' share (0..0.15): the escapes'
  // best less its two maps that pay least is re-optimised, then maps are added one at a time
  // onto the largest regions of L that A misses and the whole set re-optimised after each, until
  // N again; the grown set competes with the escapes' best for the working raster's stage.
  // 0 = none, the default: at a fixed evaluation count it did not gain (−0.001 on average at 512²
  // over seven shapes and two seeds, a tenth of the stages; bench/README.md).
  double grow_share = 0;
  // moments: CMA-ES runs after the first, each from a seeded k-means++ split. search: runs
  // after the first that start from the next-best choice of maps from the pool; later runs
  // kick the best maps so far, for as long as the budget lasts.
  int restarts = 5;
  // Objective evaluations over the whole fit: what ends it reproducibly. A move of one map in
  // a descent counts 1/N, a move on W^k(L) counts k, an attractor loss one per 20000 of its
  // chaos-game points and canvas pixels (1.3 on 64², 4.6 on 128²), about the same time as one
  // collage evaluation.
  long max_evaluations = 250000;
  // Wall-clock cap over the whole fit, rendering included (seconds); 0 = none (then the same
  // seed gives the same maps on any machine and thread count). The stages have shares of it (and
  // of max_evaluations); work is cut only between units whose result does not depend on the
  // thread count (a CMA-ES generation, a descent step, an ICP round, a searched partition), and
  // a rendering that would not end in time is not started, so the fit ends on time by design:
  // a slow or loaded machine does fewer units, never different ones, and its fit is worse, not
  // longer.
  double max_seconds = 30;
  int threads = 0;              // 0 = all cores
  double quality = 256;         // chaos-game points per pixel for the attractors
  std::string name = "fitted";  // the IFS's name
  ObjectiveOptions objective;
  // ICP rounds (refine.h) after each run's search; the refined maps replace the searched ones
  // when their attractor matches L better. 0 = no refinement.
  int refine_iterations = 30;
  // Initialisation::search: partitions of L whose searched maps make the pool the runs choose
  // from (the first is always searched; the others while the time allows), and the search
  // itself (its threads and cancel are the fit's).
  int partitions = 4;
  SearchOptions search;
  // Optional: the target on a finer raster of the same frame (working_raster of the same mask at
  // a larger size, e.g. 4S); the report's fine_iou is measured there, FitMethod::attractor cuts
  // its loss's levels from it (thin parts count) and finishes on it, and every candidate is
  // judged on it too: the best there is the result.
  cv::Mat fine_target;
  // Called after every CMA-ES generation and at every change of phase, on the calling thread
  // (the library never prints).
  std::function<void(const FitProgress&)> progress;
  // Polled between candidates and refinement steps; a stop request throws Error{interrupted}.
  CancelToken cancel;
};

struct FitResult {
  Ifs ifs;               // N maps on the unit square, probabilities ∝ |det| (docs/design.md §1)
  CollageReport report;  // of the chosen run
  double objective = 0;  // its collage objective
  long evaluations = 0;  // all runs
  int runs = 0;          // runs done
  double seconds = 0;
  bool time_capped = false;  // max_seconds cut the search short
  bool interrupted = false;  // the cancel token stopped the fit; the best so far is kept
};

// Fits N maps to `target` (a working raster). Initialisation::moments: every run starts from a
// moment-matched split, minimises the CollageObjective by CMA-ES, then refines the maps to
// sub-pixel precision by ICP. Initialisation::search: the searched maps are pooled; runs choose
// N of them and move one map at a time on the collage objective (combine.h), the best run is
// refined by CMA-ES and ICP, and last the maps are moved on the attractor's picture W^k(L)
// (CollageObjective::iterated). Of all candidates, the one whose rendered attractor overlaps L
// best (IoU) wins.
//   auto result = fit(working_raster(load_target("hand.png")), {.maps = 10});
// FitMethod::attractor adds the attractor's own stages after these (see FitMethod).
// A stop request (options.cancel) ends the fit with the best IFS so far (result.interrupted);
// it throws Error{interrupted} only when nothing was found yet.
// Throws Error{invalid_argument} for N outside 1..32 or above the number of pixels of L.
FitResult fit(const cv::Mat& target, const FitOptions& options = {});

}  // namespace ifsfx::collage
