// SPDX-License-Identifier: Apache-2.0
// How a movie's pictures are to be shown: the display matrix a phone writes (ISO BMFF `tkhd`
// matrix, FFmpeg's AV_PKT_DATA_DISPLAYMATRIX side data) or the older `rotate` tag. FileSource
// turns every frame upright before the filter sees it, so the fractal is laid over the picture as
// the user sees it, and the output carries no rotation of its own.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

namespace ifsfx::video {

// A turn by a multiple of 90° with an optional mirror, as a transpose then flips: the display
// picture is the coded one transposed (when `transpose`), then mirrored left-right (`flip_x`) and
// top-bottom (`flip_y`). The identity leaves frames alone.
struct Orientation {
  bool transpose = false;
  bool flip_x = false;
  bool flip_y = false;

  bool identity() const { return !transpose && !flip_x && !flip_y; }
  cv::Size displayed(cv::Size coded) const;  // width and height swap on a quarter turn
  cv::Mat apply(const cv::Mat& coded) const;
  // "turned 90° clockwise", "mirrored left-right", ... for messages and --help.
  std::string describe() const;
};

// The orientation of a display matrix (nine 16.16/2.30 fixed-point numbers, FFmpeg's layout
// {a b u; c d v; x y w}: a display point is (a·x + c·y, b·x + d·y) of a coded point (x, y)).
// Throws Error{unsupported} naming `what` for a turn that is not a multiple of 90°
// (e.g. "rotated by 30°").
Orientation orientation_from_matrix(const std::int32_t matrix[9], const std::string& what);

// The orientation of a `rotate` tag: degrees clockwise ("90", "-90", "180", "270"). Throws
// Error{unsupported} naming `what` for any other value.
Orientation orientation_from_rotate_tag(const std::string& degrees, const std::string& what);

}  // namespace ifsfx::video
