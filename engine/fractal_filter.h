// SPDX-License-Identifier: Apache-2.0
// The fractal filter of paper §6 (Fig. 6): colour stealing (§4) with each video frame as the
// colour source. The steal map T(x) = π_G(τ_F(x)) does not depend on the frame (docs/design.md §3),
// so it is computed once and turned here into a remap table in the frame's pixels; each frame is
// then one remap, plus the optional blend with the original frame.
#pragma once

#include <opencv2/core.hpp>

#include "ifs/steal_map.h"

namespace ifsfx::engine {

// What shows where the attractor does not cover the output.
enum class BackgroundKind { colour, original };

struct Background {
  BackgroundKind kind = BackgroundKind::colour;
  cv::Scalar colour = cv::Scalar::all(0);  // BGR, 0..255 (kind == colour): the frame's channel
                                           // order, so swap it for RGBA frames

  friend bool operator==(const Background&, const Background&) = default;
};

// Parses a background: "black", "white", "original", "#rrggbb" or "R,G,B" (0..255 each); throws
// Error{parse} naming `what`.
Background parse_background(const std::string& text, const std::string& what = "background");

struct FilterOptions {
  Interpolation interpolation = Interpolation::bilinear;
  // Weight of the original frame (resized to the output) blended over the fractal: 0 = the
  // fractal alone, 1 = the original alone.
  double mix = 0;
  Background background;
  int threads = 0;  // 0 = all cores
};

// Checks the options: mix in [0, 1]; throws Error{invalid_argument} naming --mix.
void check_filter_options(const FilterOptions& options);

// The steal map prepared for frames of `frame_size` with a transparent border, so that one remap
// over the background drawn first leaves it where the attractor does not reach: prepare_apply
// (ifs/steal_map.h) with {interpolation, RemapBorder::transparent, threads}.
PreparedStealMap prepare_filter(const StealMap& map, cv::Size frame_size,
                                Interpolation interpolation = Interpolation::bilinear,
                                int threads = 0);

// The filtered frame: `frame` (of table.source_size) coloured through the table, of the table's
// size and the frame's type. Frames are CV_8UC3 (BGR) or CV_8UC4, whose fourth channel (alpha) is
// not stolen but passed through from the same place of the original frame. The table has a
// transparent border (prepare_filter); throws Error{invalid_argument} otherwise, and for a frame
// check_apply_source refuses or of another type.
//   auto table = prepare_filter(T, frame.size());
//   cv::Mat out = filter_frame(frame, table);
cv::Mat filter_frame(const cv::Mat& frame, const PreparedStealMap& table,
                     const FilterOptions& options = {});
// The same into `out`, reallocated only when its size or type differ: a host's frame buffer
// wrapped in a cv::Mat is written in place.
void filter_frame(const cv::Mat& frame, const PreparedStealMap& table, const FilterOptions& options,
                  cv::Mat& out);

// A cross-fade between two tables of the same size: (1 − t)·through `from` + t·through `to`, for
// animations that change the map (a superIFS step, drift keyframes).
cv::Mat filter_frame(const cv::Mat& frame, const PreparedStealMap& from, const PreparedStealMap& to,
                     double t, const FilterOptions& options = {});
void filter_frame(const cv::Mat& frame, const PreparedStealMap& from, const PreparedStealMap& to,
                  double t, const FilterOptions& options, cv::Mat& out);

}  // namespace ifsfx::engine
