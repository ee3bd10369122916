// SPDX-License-Identifier: Apache-2.0
// A loss on the attractor A itself (issue 32), where the collage objective (collage.h) judges one
// step of W: by the collage theorem (paper eq. 3) h(L, A) may be up to 1/(1 − s) times h(L, W(L)),
// 5–7× at the contractions fits end with, and nothing in the collage measures that.
//
// A is rendered by the chaos game with common random numbers: the draws that pick the maps are
// fixed when the loss is built, so every candidate an optimiser proposes is rendered with the
// same draws (Tu et al., "Learning Fractals by Gradient Descent", AAAI 2023, fix the map sequence
// the same way). The loss is then a deterministic function of the maps, and the points move
// continuously with them. On a raster of side R (a level: 32, 64, … up to the working raster):
//   value = (1 − IoU(L, A)) + w_spill · mean_{a ∈ A} d(a, L) + w_cover · mean_{p ∈ L} d(p, A)
//         + w_s · max(0, s − s_soft)²
// The two distance terms (plane units, from distance transforms of L and of A's raster) tell a
// near miss from a far one, where the IoU alone is flat: spill pulls stray points back into L,
// coverage pulls A towards the parts of L it leaves empty. Overlap of the pieces is not
// penalised: overlapping copies fill notches where the shape is solid.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/cpu.h"

namespace ifsfx::collage {

struct AttractorLossOptions {
  int size = 64;              // R, the level's raster side (8 .. the working raster's side)
  double points = 4;          // chaos-game points per pixel of the R×R square
  double spill = 4;           // w_spill, per plane unit
  double coverage = 4;        // w_cover, per plane unit
  double soft_factor = 0.85;  // s_soft: contraction above which the penalty starts
  double contraction = 2;     // w_s
  std::uint64_t seed = 1;     // the common random numbers
  // A pixel of the level is part of L where L covers more than this fraction of it. 0.5 suits
  // a solid shape; 0 (any part) is what A's raster means — a pixel is A's when any point lands
  // in it — and keeps the thin parts of a finer target that half cover would drop (a fern's
  // fronds are a pixel wide at 512², a quarter of a pixel at 128²).
  double keep = 0.5;
  // The chaos game's kernels (collage/detail/play_kernel.h): every level gives the same bits;
  // none = cpu_level(). Tests set it to compare the levels.
  std::optional<CpuLevel> level;
};

struct AttractorTerms {
  double iou = 0;       // |L ∩ A| / |L ∪ A| on the level's raster (A beyond it left out)
  double spill = 0;     // mean distance of A's points from L, plane units
  double coverage = 0;  // mean distance of L's pixels from A's, plane units
  double contraction = 0;
  double value = 0;
};

// The loss of one target at one level. Build once; evaluation is const and thread-safe.
class AttractorLoss {
 public:
  // `target`: the working raster (target.h) or a finer raster of its frame; it is resampled to R
  // by area and kept where it covers more than options.keep of a pixel.
  // Throws Error{invalid_argument} for R outside 8..target side or a target that vanishes at R.
  AttractorLoss(const cv::Mat& target, const AttractorLossOptions& options = {});

  double operator()(std::span<const AffineMap> maps) const { return terms(maps).value; }
  AttractorTerms terms(std::span<const AffineMap> maps) const;

  // A as the loss sees it: the R×R raster of the pixels its points hit (CV_8UC1 0/255).
  cv::Mat raster(std::span<const AffineMap> maps) const;

  int size() const { return size_; }
  int canvas_side() const { return side_; }  // the hit raster's: R and R/4 on every side
  double points() const { return options_.points; }
  const cv::Mat& target() const { return target_; }  // L at R, CV_8UC1 0/255

 private:
  // Runs the chaos game: marks the canvas pixels hit (when `hits` is given) and returns the
  // summed distance of the points from L (pixels).
  double play(std::span<const AffineMap> maps, std::vector<std::uint8_t>* hits) const;

  int size_ = 0;
  int pad_ = 0;   // the canvas reaches pad_ pixels beyond the square on every side
  int side_ = 0;  // size_ + 2 pad_
  cv::Mat target_;
  // The canvas's distance to L's nearest pixel centre, by cells of four corners
  // (collage/detail/play_kernel.h).
  std::vector<float> cells_;
  std::vector<int> inside_;           // canvas indices of L's pixels
  std::vector<cv::Point> inside_at_;  // and their (column, row): no division per pixel
  cv::Rect bounds_;                   // their bounding box on the canvas
  std::vector<float> draws_;          // the common random numbers, uniform in [0, 1), step-major
  CpuLevel level_ = CpuLevel::scalar;
  AttractorLossOptions options_;
};

}  // namespace ifsfx::collage
