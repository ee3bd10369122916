// SPDX-License-Identifier: Apache-2.0
// Distances between shapes on one raster: the Hausdorff distance h of the collage theorem
// (paper eq. 3), the mean (chamfer) distance, and the intersection over union.
//
// A mask (CV_8UC1, non-zero = in the set) stands for the finite set of its pixel centres; all
// distances are Euclidean, in pixels, between those centres, and exact for those sets.
#pragma once

#include <opencv2/core.hpp>

namespace ifsfx::collage {

// The exact Euclidean distance transform: for every pixel, the distance (pixels) from its centre
// to the nearest centre of a pixel of `mask`. CV_32FC1 of the mask's size. Throws
// Error{invalid_argument} for an empty mask (the distance to nothing is undefined).
cv::Mat distance_to(const cv::Mat& mask);

// An upper bound of the distance (pixels) from the continuous pixel point (qx, qy) — pixel
// (col, row) covers [col, col+1) × [row, row+1) — to the set whose distance_to() is `distance`:
// the distance at the pixel nearest to q (clamped into the raster) plus the way from q to that
// pixel's centre. Exact at pixel centres inside the raster.
double distance_bound(const cv::Mat& distance, double qx, double qy);

// The distance from (qx, qy) interpolated bilinearly between pixel centres (pixels): continuous
// in q, so that an optimiser feels sub-pixel moves; outside the centres' square, distance_bound.
double interpolated_distance(const cv::Mat& distance, double qx, double qy);

// max over a of the distance from a to b (the directed Hausdorff distance), pixels. Both masks
// the same size and non-empty.
double directed_hausdorff(const cv::Mat& a, const cv::Mat& b);

// The Hausdorff distance h(a, b) = max(directed(a, b), directed(b, a)), pixels.
double hausdorff(const cv::Mat& a, const cv::Mat& b);

// The symmetric mean distance (mean over a of d(·, b) + mean over b of d(·, a)) / 2, pixels:
// the smooth cousin of h that tells how far the bulk of one shape lies from the other.
double chamfer(const cv::Mat& a, const cv::Mat& b);

// |a ∩ b| / |a ∪ b| in [0, 1]; 1 when both are empty.
double iou(const cv::Mat& a, const cv::Mat& b);

}  // namespace ifsfx::collage
