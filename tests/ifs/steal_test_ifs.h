// SPDX-License-Identifier: Apache-2.0
// IFSs built in code for the tops and steal map tests, so that they do not depend on presets.
#pragma once

#include <cmath>
#include <filesystem>

#include <opencv2/core.hpp>

#include "ifs/ifs.h"
#include "ifs/image_io.h"

namespace ifsfx::testing {

// The k×k square tiling of the unit square, tiles in raster order from the bottom-left.
inline Ifs square_tiling(int k) {
  Ifs t;
  t.name = "square-tiling";
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i)
      t.maps.push_back(
          {1.0 / k, 0, 0, 1.0 / k, static_cast<double>(i) / k, static_cast<double>(j) / k});
  return t;
}

// Four maps of factor s into the corners of the unit square, in raster order from the
// bottom-left: for s > 1/2 the pieces overlap and the attractor is the square.
inline Ifs corners(double s) {
  Ifs t;
  t.name = "corners";
  const double o = 1 - s;
  t.maps = {{s, 0, 0, s, 0, 0}, {s, 0, 0, s, o, 0}, {s, 0, 0, s, 0, o}, {s, 0, 0, s, o, o}};
  return t;
}

inline Ifs fern() {
  Ifs t;
  t.name = "fern";
  t.maps = {{0, 0, 0, 0.16, 0, 0},
            {0.85, 0.04, -0.04, 0.85, 0, 1.6},
            {0.2, -0.26, 0.23, 0.22, 0, 1.6},
            {-0.15, 0.28, 0.26, 0.24, 0, 0.44}};
  t.probabilities = {0.01, 0.85, 0.07, 0.07};
  return t;
}

inline Ifs maple_leaf() {
  Ifs t;
  t.name = "maple-leaf";
  t.maps = {{0.14, 0.01, 0.00, 0.51, -0.08, -1.31},
            {0.43, 0.52, -0.45, 0.50, 1.49, -0.75},
            {0.45, -0.49, 0.47, 0.47, -1.62, -0.74},
            {0.49, 0.00, 0.00, 0.51, 0.02, 1.62}};
  t.probabilities = {0.10, 0.35, 0.35, 0.20};
  return t;
}

// A real photograph shipped by Debian's opencv-doc (512×512 BGR).
inline std::filesystem::path photo_path() {
  return "/usr/share/doc/opencv-doc/examples/data/baboon.jpg";
}

inline double psnr(const cv::Mat& a, const cv::Mat& b) {
  return cv::PSNR(a, b, 255);
}

}  // namespace ifsfx::testing
