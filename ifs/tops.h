// SPDX-License-Identifier: Apache-2.0
// Fractal tops (paper §3, eq. 4–9; docs/design.md §2): the top address of each pixel of an IFS's
// attractor — its largest address, so that where pieces overlap the higher-numbered map is on
// top — and pictures of it, each pixel coloured by the first (and optionally second) symbol.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/ifs.h"
#include "ifs/sampling.h"
#include "ifs/view.h"

namespace ifsfx {

struct TopsOptions {
  Sampling sampling;           // view, margin, quality (chaos game), seed, threads, cancel
  bool exact = true;           // per-pixel descent (docs/design.md §3); false: the chaos game
  bool second_symbol = false;  // render_tops: mix in the colour of the second symbol
};

// The first two symbols of each pixel's top address (0-based map indices) and where the
// attractor is. `first`, `second`: CV_16UC1, 0 off the attractor; `coverage`: CV_8UC1, 255 on it.
struct TopSymbols {
  cv::Mat first, second, coverage;
  Box view;                  // the plane rectangle shown
  std::uint64_t points = 0;  // chaos-game points plotted (for the exact descent: its mask's)
};

// Top symbols by the chaos game (64-bit address keys, largest key wins per pixel) or exactly.
//   auto tops = top_symbols(fern, {512, 512}, {.exact = true});
TopSymbols top_symbols(const Ifs& F, cv::Size size, const TopsOptions& options = {});

// Each pixel coloured by the first symbol of its top address through the IFS's colours or the
// default palette (palette_colour); with `second_symbol`, the colour is (2·c(σ1) + c(σ2)) / 3,
// so each piece shows its sub-pieces. CV_32FC4 BGRA in [0, 1]; alpha 1 on the attractor, 0 off.
// `points`, when given, receives TopSymbols::points.
cv::Mat render_tops(const Ifs& F, cv::Size size, const TopsOptions& options = {},
                    std::uint64_t* points = nullptr);

// The same picture from symbols already found (a flame's, flame/flame_chaos.h), each map n
// coloured `colours[n]` (one per map).
cv::Mat render_tops(const TopSymbols& tops, const std::vector<Rgb>& colours, bool second_symbol);

// The colour of each map in a tops picture: the IFS's colours, or palette_colour(n, N).
std::vector<Rgb> map_colours(const Ifs& F);

}  // namespace ifsfx
