// SPDX-License-Identifier: Apache-2.0
// SuperIFSs with known answers for the superifs tests, built in code (no preset files).
#pragma once

#include <cmath>

#include <opencv2/core.hpp>

#include "known_ifs.h"
#include "superifs/superifs.h"

namespace ifsfx::testing {

// The corners of the equilateral triangle of side 1 with its base on y = 0.
inline Point triangle_corner(int m) {
  const Point v[3] = {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
  return v[m];
}

// Sierpinski triangle of factor s: f_m(x) = s·x + (1 − s)·v_m, each corner v_m fixed.
inline Ifs sierpinski_of_factor(double s) {
  Ifs f;
  for (int m = 0; m < 3; ++m) {
    const Point v = triangle_corner(m);
    f.maps.push_back({s, 0, 0, s, (1 - s) * v.x, (1 - s) * v.y});
  }
  return f;
}

// The paper's Fig. 4 superIFS: F^1 of factor 1/2, F^2 of factor 1/3 (M = 3, N = 2).
inline SuperIfs paper_fig4() {
  SuperIfs s;
  s.name = "fig4";
  s.ifs = {sierpinski_of_factor(0.5), sierpinski_of_factor(1.0 / 3)};
  return s;
}

// |A ∩ B| / |A ∪ B| of two masks (1 when both are empty).
inline double iou(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat both, either;
  cv::bitwise_and(a != 0, b != 0, both);
  cv::bitwise_or(a != 0, b != 0, either);
  const int u = cv::countNonZero(either);
  return u == 0 ? 1.0 : static_cast<double>(cv::countNonZero(both)) / u;
}

}  // namespace ifsfx::testing
