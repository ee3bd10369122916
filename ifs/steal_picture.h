// SPDX-License-Identifier: Apache-2.0
// What a steal map's colours become in a picture: the background colour at an image's depth, and
// the coverage as the alpha channel; and the tops picture made the same way. One copy for
// `ifsfx render` (tops and steal), `ifsfx apply`, the studio and the Python module, so that their
// pictures are the same bytes.
#pragma once

#include <opencv2/core.hpp>

#include "ifs/ifs.h"
#include "ifs/tops.h"

namespace ifsfx {

// The background colour as a cv::Scalar in BGR(A) order at `depth`'s full scale (255 for CV_8U,
// 65535 for CV_16U, 1 otherwise), alpha 0.
cv::Scalar background_scalar(const Rgb& colour, int depth);

// The map's pixels from `coloured` (any depth; 1, 3 or 4 channels) and `coverage` (CV_8UC1, 255
// where the map covers). With `alpha`: BGRA whose alpha is the coverage at the image's scale (a
// 4-channel `coloured` keeps its own alpha: the source's, 0 off the attractor). Without: BGR (a
// 4-channel image loses its alpha) or grey, as given.
cv::Mat with_coverage_alpha(const cv::Mat& coloured, const cv::Mat& coverage, bool alpha);

// What render_tops drew, for a caller that reports it.
struct TopsPictureStats {
  Box view;                  // the plane rectangle shown
  std::uint64_t points = 0;  // chaos-game points plotted (0 for the exact descent: its mask's
                             // points are not the picture's work)
  double coverage = 0;       // fraction of pixels on the attractor
};

// render_tops (CV_32F) with `background` off the attractor: BGRA whose alpha is the coverage with
// `alpha`, else BGR.
cv::Mat tops_picture(const Ifs& F, cv::Size size, const TopsOptions& options, const Rgb& background,
                     bool alpha, TopsPictureStats* stats = nullptr);

// The same from a render_tops picture already made (CV_32FC4, alpha the coverage): `background`
// off the attractor, BGRA with `alpha`, else BGR. Fills stats->coverage only.
cv::Mat tops_picture(cv::Mat tops, const Rgb& background, bool alpha,
                     TopsPictureStats* stats = nullptr);

}  // namespace ifsfx
