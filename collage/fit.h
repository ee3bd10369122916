// Collage-theorem fitting (paper §2, eq. 3; DESIGN.md §6): search N affine maps whose collage
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

#include <opencv2/core.hpp>

#include "collage/collage.h"
#include "ifs/cancel.h"
#include "ifs/ifs.h"

namespace ifsfx::collage {

// What the collage theorem says about an IFS against a target, and what its attractor does.
struct CollageReport {
  double collage_distance = 0;  // h(L, W(L)), plane units, never below the exact value
  double contraction = 0;       // s, the largest factor of the maps
  double lower_bound = 0;       // h(L, W(L)) / (1 + s) ≤ h(L, A)
  double upper_bound = 0;       // h(L, A) ≤ h(L, W(L)) / (1 − s); +inf when s ≥ 1
  double hausdorff = 0;         // h(L, A) measured on the raster: L against the pixels A hits
  double iou = 0;               // |L ∩ A| / |L ∪ A| on the raster (A outside the square counts)
  double collage_iou = 0;       // |L ∩ W(L)| / |L ∪ W(L)| on the raster
  double pixel = 0;             // the raster's pixel size in plane units, 1/S
  bool clipped = false;  // A reaches beyond the measuring canvas (the square grown by 1 each way)
  cv::Mat collage;       // W(L) on the working raster, CV_8UC1 0/255
  cv::Mat attractor;     // A on the working raster, CV_8UC1 0/255
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

struct FitProgress {
  int run = 0;           // 0: from the principal-axes split; 1..: restarts from k-means++
  int runs = 0;          // runs planned
  long evaluations = 0;  // objective evaluations so far, all runs
  double objective = 0;  // best value of this run so far
  double best = 0;       // best value of all runs so far
  double seconds = 0;    // since the fit started
};

struct FitOptions {
  int maps = 4;  // N, 1..32
  std::uint64_t seed = 1;
  int restarts = 5;              // CMA-ES runs after the first, each from a seeded k-means++ split
  long max_evaluations = 60000;  // objective evaluations over all runs (what makes it reproducible)
  double max_seconds = 30;       // wall-clock cap over all runs; 0 = none (then the same seed gives
                                 // the same maps on any machine and thread count)
  int threads = 0;               // 0 = all cores
  double quality = 256;          // chaos-game points per pixel for the attractors
  std::string name = "fitted";   // the IFS's name
  ObjectiveOptions objective;
  // ICP rounds (refine.h) after each run's search; the refined maps replace the searched ones
  // when their attractor matches L better. 0 = no refinement.
  int refine_iterations = 30;
  // Called after every CMA-ES generation on the calling thread (the library never prints).
  std::function<void(const FitProgress&)> progress;
  CancelToken cancel;  // polled per generation and per run: Error{interrupted} on a stop request
};

struct FitResult {
  Ifs ifs;               // N maps on the unit square, probabilities ∝ |det| (DESIGN.md §1)
  CollageReport report;  // of the chosen run
  double objective = 0;  // its collage objective
  long evaluations = 0;  // all runs
  int runs = 0;          // runs done
  double seconds = 0;
  bool time_capped = false;  // max_seconds cut the search short
};

// Fits N maps to `target` (a working raster): every run starts from an initial_maps() split,
// minimises the CollageObjective by CMA-ES, then refines the maps to sub-pixel precision by ICP;
// of all these candidates, the one whose rendered attractor overlaps L best (IoU) wins.
// Throws Error{invalid_argument} for N outside 1..32 or above the number of pixels of L.
FitResult fit(const cv::Mat& target, const FitOptions& options = {});

}  // namespace ifsfx::collage
