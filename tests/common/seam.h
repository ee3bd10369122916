// SPDX-License-Identifier: Apache-2.0
// The seam statistic of a seamless tile (docs/seamless.md): in the 2×2 tiling of the tile, the
// mean absolute difference between neighbours across the tile's edges (its last column and its
// first, its last row and its first), over that between neighbours inside it (every other pair of
// horizontal or vertical neighbours), all channels together. About 1 for a tile whose edges are
// like any other line of it; a seam shows as a ratio well above 1.
#pragma once

#include <cmath>

#include <opencv2/core.hpp>

namespace ifsfx::testing {

struct SeamStatistic {
  double across_edges = 0;  // mean absolute difference across the tile's edges
  double inside = 0;        // mean absolute difference between neighbours inside the tile
  double ratio() const { return inside > 0 ? across_edges / inside : (across_edges > 0 ? 1e9 : 0); }
};

inline SeamStatistic seam_statistic(const cv::Mat& tile) {
  cv::Mat m;
  tile.convertTo(m, CV_64F);
  const int w = m.cols, h = m.rows, channels = m.channels();
  double edge = 0, inside = 0;
  std::size_t edge_pairs = 0, inside_pairs = 0;
  for (int r = 0; r < h; ++r) {
    const double* row = m.ptr<double>(r);
    const double* below = m.ptr<double>((r + 1) % h);
    for (int c = 0; c < w; ++c)
      for (int k = 0; k < channels; ++k) {
        const double v = row[c * channels + k];
        const double right = std::abs(v - row[((c + 1) % w) * channels + k]);
        const double down = std::abs(v - below[c * channels + k]);
        (c == w - 1 ? edge : inside) += right;
        ++(c == w - 1 ? edge_pairs : inside_pairs);
        (r == h - 1 ? edge : inside) += down;
        ++(r == h - 1 ? edge_pairs : inside_pairs);
      }
  }
  return {edge / static_cast<double>(edge_pairs), inside / static_cast<double>(inside_pairs)};
}

}  // namespace ifsfx::testing
