// SPDX-License-Identifier: Apache-2.0
// The shape to fit: a binary mask L taken from an image (paper §2: the target L ∈ H(X) of the
// collage theorem, eq. 3), and the working raster on which the fitter sees it.
//
// Working raster convention (shared by everything in collage/): an S×S CV_8UC1 mask, 255 inside
// L, on the unit square [0, 1]² of the IFS plane with y up. Pixel (col, row) is the square
// [col/S, (col+1)/S] × [1 − (row+1)/S, 1 − row/S]; L as a point set is the set of the centres of
// its pixels, so that every distance below is exact for that finite set.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

namespace ifsfx::collage {

struct TargetOptions {
  // Grey level in [0, 1] (fraction of full scale) that separates shape from background, or the
  // alpha level when the image has an alpha channel. Default: Otsu's threshold for grey images,
  // 0.5 for alpha.
  std::optional<double> threshold;
  // Without an alpha channel the shape is the dark side of the threshold (a silhouette on a light
  // ground); with one it is the opaque side. `invert` swaps shape and background.
  bool invert = false;
};

// The shape of `image` (BGR, BGRA, grey or grey+alpha; CV_8U, CV_16U or CV_32F as read_image
// returns): CV_8UC1, 255 on the shape, 0 elsewhere, same size as the image. `what` names the
// image in errors. Throws Error{invalid_argument} for an empty or a full shape (nothing to fit)
// and for a threshold outside [0, 1].
//   auto mask = shape_mask(read_image("leaf.png").pixels);
cv::Mat shape_mask(const cv::Mat& image, const TargetOptions& options = {},
                   const std::string& what = "target");

// read_image then shape_mask; errors name the path.
cv::Mat load_target(const std::filesystem::path& path, const TargetOptions& options = {});

struct FrameOptions {
  int size = 128;        // S, the working raster's side in pixels (8..2048)
  double margin = 0.05;  // free border around the shape's bounding box, fraction of the side
};

// The working raster of a shape mask: the shape's bounding box plus `margin`, centred in a
// square (so the aspect is kept), resampled to S×S by area and thresholded at half coverage.
// Throws Error{invalid_argument} when nothing of the shape survives the resampling.
cv::Mat working_raster(const cv::Mat& mask, const FrameOptions& options = {});

// A 0/255 mask at size × size by area, a pixel kept where the mask covers more than `keep` of
// it (0: any part of it, so that parts thinner than a pixel stay), CV_8UC1 0/255.
cv::Mat resampled_mask(const cv::Mat& mask, int size, double keep = 0);

}  // namespace ifsfx::collage
