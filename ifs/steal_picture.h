// SPDX-License-Identifier: Apache-2.0
// What a steal map's colours become in a picture: the background colour at an image's depth, and
// the coverage as the alpha channel. One copy for `ifsfx render` (tops and steal), `ifsfx apply`
// and the Python module, so that their pictures are the same bytes.
#pragma once

#include <opencv2/core.hpp>

#include "ifs/ifs.h"

namespace ifsfx {

// The background colour as a cv::Scalar in BGR(A) order at `depth`'s full scale (255 for CV_8U,
// 65535 for CV_16U, 1 otherwise), alpha 0.
cv::Scalar background_scalar(const Rgb& colour, int depth);

// The map's pixels from `coloured` (any depth; 1, 3 or 4 channels) and `coverage` (CV_8UC1, 255
// where the map covers). With `alpha`: BGRA whose alpha is the coverage at the image's scale (a
// 4-channel `coloured` keeps its own alpha: the source's, 0 off the attractor). Without: BGR (a
// 4-channel image loses its alpha) or grey, as given.
cv::Mat with_coverage_alpha(const cv::Mat& coloured, const cv::Mat& coverage, bool alpha);

}  // namespace ifsfx
