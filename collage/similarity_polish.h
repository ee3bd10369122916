// SPDX-License-Identifier: Apache-2.0
// The fine half of the self-similarity scan (similarity_scan.h): a copy found on the coarse
// raster is within a grid step of the true one, and on that raster (64²) a fern is a solid leaf
// in which any smaller leaf fits. On a raster four times finer its fronds are apart, and only the
// true copies — w(L) ⊂ L exactly, paper eq. 1 — keep their points in L. Internal to collage/.
#pragma once

#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"

namespace ifsfx::collage::detail {

// L on the fine raster, and the points of L that score a copy.
class FineScene {
 public:
  // `fine`: L at any cover on the fine raster (resampled_mask); at most `samples` of its pixel
  // centres, evenly strided, score a copy.
  FineScene(const cv::Mat& fine, int samples);

  // The mean over the samples p of max(0, 1 − d(w(p), L) / 2 pixels): the share of them that w
  // moves into L, softened so that a copy a pixel off is nearly as good (a search over w then
  // climbs, where the share alone is flat between jumps). L is not grown: on 256² a fern's true
  // copies keep 0.98–1 of their points in L, copies 0.02 off 0.87–0.92 (0.99–1 both, grown).
  double precision(const AffineMap& w) const;

  int size() const { return size_; }

 private:
  int size_ = 0;
  cv::Mat distance_;           // CV_32FC1: pixels to L's nearest pixel, 0 in L
  std::vector<Point> points_;  // the samples, IFS plane
};

// A copy moved to the fine raster: precision and value as `polish` leaves them.
struct Polished {
  AffineMap map;
  double precision = 0;
  double value = 0;  // (|det w| + 0.01) · (10 · precision − 9): the largest copy that stays in L
};

// A compass search over w's linear part about `centre` (its coefficients, its scale and its
// turn, steps 0.02) and its image of the centre (steps of two pixels of the scene), each halved
// three times, for the largest value, keeping the
// contraction below `max_factor`; at most `evaluations` precisions.
Polished polish(const FineScene& scene, const AffineMap& start, Point centre, double max_factor,
                int evaluations);

// Of `maps` (best first), those that no earlier kept one is near: the images of `centre` and of
// the four points `radius` from it along the axes within `tolerance` (plane units). At most
// `keep`; returns their indices.
std::vector<std::size_t> distinct(std::span<const AffineMap> maps, Point centre, double radius,
                                  double tolerance, std::size_t keep);

}  // namespace ifsfx::collage::detail
