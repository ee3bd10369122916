// SPDX-License-Identifier: Apache-2.0
// A picture in at most 256 colours, for GIF (a FileSink whose encoder takes palette images only):
// its own colours when it has no more than 256 (then exactly, as a texture's set or tops are), else
// a median-cut palette of its colours with ordered (Bayer) dithering, which stays put from frame to
// frame where the picture does, so an animation does not crawl.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::engine {

struct IndexedImage {
  cv::Mat indices;                 // CV_8UC1: each pixel's entry in the palette
  std::vector<cv::Vec3b> palette;  // BGR, 1..256 entries
  bool exact = false;              // every pixel keeps its colour (no more than 256 of them)
};

// The palette picture of an 8-bit BGR image (CV_8UC3). Deterministic: the same image gives the
// same palette and indices. Throws Error{invalid_argument} for another type or an empty image.
//   IndexedImage gif = to_indexed(frame);  // gif.palette[gif.indices.at<uchar>(r, c)]
IndexedImage to_indexed(const cv::Mat& bgr);

}  // namespace ifsfx::engine
