// SPDX-License-Identifier: Apache-2.0
// The collage W(L) = ∪ f_n(L) of a target L under N affine maps (paper §2, eq. 2–3), its
// distance to L, and the objective the fitter minimises.
//
// Targets are working rasters (see target.h): S×S masks on the unit square of the IFS plane,
// y up; L is the finite set of the centres of its pixels. Maps act on the IFS plane.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"

namespace ifsfx::collage {

// The plane → pixel map of an S×S working raster: (x, y) ↦ (S x, S (1 − y)), continuous pixel
// coordinates in which pixel (col, row) covers [col, col+1) × [row, row+1).
AffineMap plane_to_pixel(int size);

// W(L) on the raster of `target`: CV_8UC1, 255 on every pixel that holds the image under some
// f_n of a point of L. Each pixel of L is sampled `subsamples`² times so that the pieces show
// no holes where a map stretches a direction by up to `subsamples`.
cv::Mat collage_raster(const cv::Mat& target, std::span<const AffineMap> maps, int subsamples = 2);

// h(L, W(L)) in plane units, where L is the set of pixel centres of `target` and W(L) the exact
// images of those points (not a raster). The value returned is never below the exact one and
// exceeds it by at most half a pixel diagonal (√2 / 2S): each image point is located through its
// nearest pixel centre, and the triangle inequality turns that detour into an upper bound. So
// h / (1 − s) is a true upper bound of h(L, A) for this L (the collage theorem, eq. 3).
double collage_distance(const cv::Mat& target, std::span<const AffineMap> maps);

// What the fitter minimises, and its parts (all dimensionless).
struct ObjectiveTerms {
  double collage_iou = 0;  // |L ∩ W(L)| / |L ∪ W(L)|
  double spill = 0;        // mean distance of W(L)'s points from L, plane units (interpolated)
  double overlap = 0;      // Σ|det f_n| − 1 when positive: measure spent twice, a loose tiling
  double contraction = 0;  // s = max_n s_n
  double value = 0;        // the weighted sum (lower is better)
};

struct ObjectiveOptions {
  double spill = 4;          // per plane unit of mean spill
  double overlap = 0.1;      // per unit of Σ|det| above 1
  double soft_factor = 0.8;  // contraction above which a quadratic penalty starts
  double contraction = 2;    // weight of (s − soft_factor)²
  double max_factor = 0.97;  // hard wall: beyond it the value jumps by 1 + 10 (s − max_factor)
};

// What one map f contributes to the collage objective: the pixels that f(L) hits and how far its
// points spill out of L. Every term of the objective is a union or a sum over the maps, so the
// objective of any set of maps follows from their footprints alone — which is what lets the fit
// try thousands of combinations of searched maps, and move one map at a time, cheaply.
struct Footprint {
  std::vector<std::uint64_t> hits;  // S² bits, row-major: pixels that hold some f(p), p ∈ L
  double spill = 0;                 // Σ_p d(f(p), L) over L's pixel centres p, pixels
  double det = 0;                   // |det f|
  double factor = 0;                // f's contraction
  int maps = 1;                     // how many maps it stands for (see merge)
};

// The footprint of several maps together: hits OR-ed, spills and determinants added, the largest
// factor. A combination that keeps most of its maps fixed is then scored against one merged
// footprint instead of all of them. Throws Error{invalid_argument} for no parts.
Footprint merge(std::span<const Footprint* const> parts);

// The collage objective for one target: (1 − IoU(L, W(L))) + spill + overlap + contraction
// penalties. Build once per target; evaluation is const and thread-safe (no
// shared scratch).
class CollageObjective {
 public:
  explicit CollageObjective(const cv::Mat& target, const ObjectiveOptions& options = {});

  double operator()(std::span<const AffineMap> maps) const { return terms(maps).value; }
  ObjectiveTerms terms(std::span<const AffineMap> maps) const;

  // 1 − IoU(L, W^k(L)) plus the contraction penalties of the objective: how well the k-th
  // iterate of the collage operator from L matches L. W^k(L) tends to the attractor A as k grows
  // (A is W's fixed point, paper eq. 2; the distance shrinks by s per step), so this judges what
  // the user will see, where the objective above judges one step of it. W is applied to pixel
  // centres on the raster, as for W(L) above; points leaving the raster are dropped.
  double iterated(std::span<const AffineMap> maps, int iterations) const;

  Footprint footprint(const AffineMap& f) const;
  // The terms of the maps whose footprints are `parts`: terms(maps) without recomputing them.
  ObjectiveTerms terms(std::span<const Footprint* const> parts) const;

  int size() const { return size_; }
  const cv::Mat& target() const { return target_; }
  Point centroid() const { return centroid_; }  // of L's pixel centres, IFS plane

 private:
  double contraction_penalty(double factor) const;

  int size_ = 0;
  cv::Mat target_;    // CV_8UC1, 0/255
  cv::Mat distance_;  // CV_32FC1, distance (pixels) to the nearest centre of L
  // Per cell between four pixel centres (row-major, (S − 1)²): 1 when all four are in L, so that
  // the interpolated distance is 0 anywhere in the cell.
  std::vector<std::uint8_t> deep_;
  std::vector<cv::Point2f> points_;    // centres of L's pixels, pixel coordinates
  std::vector<std::uint64_t> inside_;  // L as S² bits, row-major
  Point centroid_;
  ObjectiveOptions options_;
};

}  // namespace ifsfx::collage
