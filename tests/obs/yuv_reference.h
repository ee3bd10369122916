// SPDX-License-Identifier: Apache-2.0
// A plain reference for the filter's NV12 frames: BT.709 limited range, OBS's own matrix
// (video_format_get_parameters), chroma the mean of each 2×2 block, decoded by nearest sample.
#pragma once

#include <opencv2/core.hpp>

#include "tests/obs/obs_harness.h"

namespace ifsfx::obs_test {

Planes nv12_of(const cv::Mat& bgr);
cv::Mat bgr_of(const Planes& nv12);

}  // namespace ifsfx::obs_test
