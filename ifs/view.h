// SPDX-License-Identifier: Apache-2.0
// Where the IFS plane meets the pixel grid. The IFS plane has y up; image rows go down. A View is
// the rectangle of the plane shown on the whole raster (pixel (0,0) is its top-left corner).
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/affine_map.h"
#include "ifs/cancel.h"
#include "ifs/ifs.h"

namespace ifsfx {

// The narrowest view, relative to the magnitude of its coordinates, whose pixels double precision
// still tells apart (2^-52 relative spacing, 32768 pixels a side, a margin of 100).
inline constexpr double kMinRelativeExtent = 1e-9;

// The largest auto-framing margin, a fraction of the attractor's larger side: ten sides of empty
// plane around the attractor is far past any use.
inline constexpr double kMaxMargin = 10;

// An axis-aligned rectangle [x0, x1] × [y0, y1] of a plane.
struct Box {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  friend bool operator==(const Box&, const Box&) = default;
};

// A rectangle of the IFS plane on a raster of `size` pixels.
struct Viewport {
  Box view;
  cv::Size size;

  // The plane point at the centre of pixel (col, row).
  Point pixel_centre(int col, int row) const {
    return {view.x0 + (col + 0.5) * view.width() / size.width,
            view.y1 - (row + 0.5) * view.height() / size.height};
  }
  // Continuous pixel coordinates of a plane point: pixel (c, r) covers [c, c+1) × [r, r+1).
  Point to_pixel(Point p) const {
    return {(p.x - view.x0) * size.width / view.width(),
            (view.y1 - p.y) * size.height / view.height()};
  }
  // The affine map from the plane to continuous pixel coordinates (to_pixel as a map).
  AffineMap plane_to_pixel() const;
};

// Bounding box of the attractor of a contractive IFS, from its support function
// h(u) = max_n (u·t_n + h(M_nᵀ u)) iterated to its fixed point on a fine circle of directions:
// deterministic and tight to ~1e-5 of the attractor's size. Falls back to a chaos-game estimate
// (seeded with `seed`) when a map has factor ≥ 1. At most 5000 iterations (polling `cancel`);
// throws Error{invalid_ifs} when the box does not fit in kMaxCoordinate (ifs.h).
Box attractor_bounds(const Ifs& ifs, std::uint64_t seed = 1, const CancelToken& cancel = {});

// The smallest view with the aspect of `size` that holds `bounds` plus `margin` (a fraction of
// the larger side) on every side, centred. A degenerate box (a line or a point) gets a minimum
// extent so that the view is never empty. Throws Error{invalid_argument} "margin: ..." for a
// margin outside [0, kMaxMargin] or not a number (a NaN would frame nothing: a black picture).
Box fit_view(const Box& bounds, cv::Size size, double margin = 0.05);

// Parses "x0,y0,x1,y1" (a view); throws Error{parse} naming `what`.
Box parse_box(const std::string& text, const std::string& what = "view");

// Parses "WxH" (a size), 1..32768 on each side; throws Error naming `what`.
cv::Size parse_size(const std::string& text, const std::string& what = "size");

// Checks a raster size: each side in 1..32768 (Error{invalid_argument} otherwise).
void check_size(cv::Size size, const std::string& what = "size");

// Checks a view: x0 < x1, y0 < y1, all finite (Error{invalid_argument} "view: ..." otherwise).
void check_view(const Box& view, const std::string& what = "view");

}  // namespace ifsfx
