// SPDX-License-Identifier: Apache-2.0
// A partition of L for the range/domain search (search.h) shaped like the self-similar shapes of
// nature (issue 32): one large range that is L without one end of it, the rest split into small
// ones. Barnsley's fern is its own copy shrunk by 0.85 and moved up, plus two leaflets and a stem
// at the bottom; a tree is its crown's copies on a trunk. Equal-sized ranges (initialise.h) never
// contain such a large copy, so the search never proposes the map that makes the shape.
#pragma once

#include <opencv2/core.hpp>

namespace ifsfx::collage {

// Labels as partition() gives them (CV_32SC1, −1 outside L): label 0 is L less the `end` share of
// its pixels at one end of its principal axis (the low end when `from_low`), labels 1..n−1 split
// that end by partition() (by component). n ≥ 2; end in (0, 1). Throws Error{invalid_argument}
// otherwise, or when the end has fewer than n − 1 pixels.
cv::Mat cut_partition(const cv::Mat& target, int n, double end, bool from_low);

}  // namespace ifsfx::collage
