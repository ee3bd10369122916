// The collage W(L) = ∪ f_n(L) of a target L under N affine maps (paper §2, eq. 2–3), its
// distance to L, and the objective the fitter minimises.
//
// Targets are working rasters (see target.h): S×S masks on the unit square of the IFS plane,
// y up; L is the finite set of the centres of its pixels. Maps act on the IFS plane.
#pragma once

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

// The collage objective for one target: (1 − IoU(L, W(L))) + spill + overlap + contraction
// penalties. Build once per target; evaluation is const and thread-safe (no
// shared scratch).
class CollageObjective {
 public:
  explicit CollageObjective(const cv::Mat& target, const ObjectiveOptions& options = {});

  double operator()(std::span<const AffineMap> maps) const { return terms(maps).value; }
  ObjectiveTerms terms(std::span<const AffineMap> maps) const;

  int size() const { return size_; }
  const cv::Mat& target() const { return target_; }

 private:
  int size_ = 0;
  cv::Mat target_;                   // CV_8UC1, 0/255
  cv::Mat distance_;                 // CV_32FC1, distance (pixels) to the nearest centre of L
  std::vector<cv::Point2f> points_;  // centres of L's pixels, pixel coordinates
  ObjectiveOptions options_;
};

}  // namespace ifsfx::collage
