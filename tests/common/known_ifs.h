// SPDX-License-Identifier: Apache-2.0
// IFSs with known answers, built in code so the tests do not depend on preset files.
#pragma once

#include <cmath>

#include "ifs/ifs.h"

namespace ifsfx::testing {

// Barnsley's fern, with its classic probabilities.
inline Ifs barnsley_fern() {
  return {"barnsley-fern",
          {{0.00, 0.00, 0.00, 0.16, 0.00, 0.00},
           {0.85, 0.04, -0.04, 0.85, 0.00, 1.60},
           {0.20, -0.26, 0.23, 0.22, 0.00, 1.60},
           {-0.15, 0.28, 0.26, 0.24, 0.00, 0.44}},
          {0.01, 0.85, 0.07, 0.07},
          {}};
}

// x/2 + {(0,0), (1/2,0), (0,1/2)}: the right Sierpinski triangle in the unit square.
inline Ifs right_sierpinski() {
  return {"right-sierpinski",
          {{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 0.5, 0}, {0.5, 0, 0, 0.5, 0, 0.5}},
          {},
          {}};
}

// The equilateral Sierpinski triangle with side 1 and base on y = 0.
inline Ifs sierpinski_triangle() {
  const double h = std::sqrt(3.0) / 4;
  return {"sierpinski-triangle",
          {{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 0.5, 0}, {0.5, 0, 0, 0.5, 0.25, h}},
          {},
          {}};
}

// The 2^k × 2^k grid tiling of the unit square (k = 1: the four quadrants), tiles in raster order
// from the bottom-left.
inline Ifs square_grid(int cells_per_side) {
  Ifs ifs;
  ifs.name = "square-grid";
  const double s = 1.0 / cells_per_side;
  for (int j = 0; j < cells_per_side; ++j)
    for (int i = 0; i < cells_per_side; ++i) ifs.maps.push_back({s, 0, 0, s, i * s, j * s});
  return ifs;
}

// The Sierpinski carpet: the eight outer thirds of the unit square (the middle one left out), in
// raster order from the bottom-left.
inline Ifs sierpinski_carpet() {
  Ifs ifs;
  ifs.name = "sierpinski-carpet";
  const double s = 1.0 / 3;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (i != 1 || j != 1) ifs.maps.push_back({s, 0, 0, s, i * s, j * s});
  return ifs;
}

}  // namespace ifsfx::testing
