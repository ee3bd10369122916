// SPDX-License-Identifier: Apache-2.0
// From a flame's histogram to pixels (Draves & Reckase §4, §6, §7; docs/flames.md "Rendering"):
//
//   1. log density, per bin of a hits: every channel × ls(a) = k1·log(1 + k2·a)/a, where
//      k1 = contrast·brightness·268/256 and k2 = ss²/(contrast·area·q), area the picture's
//      size in flame-plane units², q the samples per pixel (with the zoom's 4^zoom);
//   2. density estimation: each bin spread over a disc whose radius shrinks with its density,
//      1.1·R/a^curve bins (1.05 with supersampling; between the minimum and R), by the
//      Gaussian e^(−4.5·d²/r²), normalised — flam3-render's kernel and radius as measured
//      (render_tone.cpp);
//   3. the spatial filter: a separable kernel `filter_shape` of radius `filter` pixels, summed
//      from the supersampled bins into each pixel;
//   4. the display, per pixel of density α (the log-scaled alpha): the gamma curve α^(1/γ),
//      linear below gamma_threshold; colour × vibrancy·α^(1/γ)/α plus (1 − vibrancy)·channel^(1/γ);
//      highlight_power ≥ 0 desaturates a clipped colour rather than change its hue; the
//      background shows through 1 − α^(1/γ).
// Values are flam3's: a hit adds the palette colour × opacity (each in [0, 1]), an output of
// 256 is full white (8-bit output clips at 255).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "flame/flame.h"
#include "ifs/cancel.h"
#include "ifs/large_buffer.h"

namespace ifsfx::flame {

// A raster of RGBA sums in row order: r, g, b, a per bin.
struct FlameHistogram {
  int width = 0, height = 0;
  // Raster-sized (8 MB at 256 px supersampled twice): huge pages spare its first touch's faults.
  std::vector<double, LargeBufferAllocator<double>> rgba;
  FlameHistogram() = default;
  FlameHistogram(int w, int h) : width(w), height(h), rgba(4 * static_cast<std::size_t>(w) * h) {}
  double* at(int row, int col) { return &rgba[4 * (static_cast<std::size_t>(row) * width + col)]; }
  const double* at(int row, int col) const {
    return &rgba[4 * (static_cast<std::size_t>(row) * width + col)];
  }
};

// ls(a) = k1·log(1 + k2·a)/a.
struct LogScale {
  double k1 = 1, k2 = 1;
  double operator()(double a) const;
};

// The constants of `flame` rendered with `ss` bins per pixel side at `quality` samples per
// pixel (the zoom's 4^zoom applied here).
LogScale log_scale(const Flame& flame, int ss, double quality);

// Steps 1 and 2: the log-scaled histogram, each bin spread by density estimation (none when
// estimator_radius is 0). Radii are in output pixels (× ss bins).
FlameHistogram density_estimate(const FlameHistogram& hist, const Filtering& filtering, int ss,
                                const LogScale& scale, int threads, const CancelToken& cancel = {});
// The same from a histogram the caller gives up: without reach (estimator_radius·ss below one
// bin, where each bin keeps its own log-scaled value) it is scaled in place, sparing a
// raster-sized buffer and its first touch; otherwise as above.
FlameHistogram density_estimate(FlameHistogram&& hist, const Filtering& filtering, int ss,
                                const LogScale& scale, int threads, const CancelToken& cancel = {});

// The spatial filter's weights along one axis (the 2-D kernel is their outer product, summing
// to 1): `width` taps, and the gutter (width − ss)/2 bins it reads beyond the picture.
struct SpatialKernel {
  int width = 1;
  int gutter = 0;
  std::vector<double> taps;
};
// Throws Error{invalid_argument} naming an unknown filter_shape.
SpatialKernel spatial_kernel(const std::string& shape, double radius, int ss);

// Step 3: picture pixel (i, j) = Σ taps[u]·taps[v]·bins[i·ss + u][j·ss + v].
FlameHistogram spatial_filter(const FlameHistogram& bins, const SpatialKernel& kernel, int ss,
                              int width, int height, int threads, const CancelToken& cancel = {});

// Step 4 on one pixel: rgba (after steps 1–3) to the display's r, g, b in [0, 256] and its
// alpha in [0, 1] (not yet clipped to 255).
struct DisplayPixel {
  double r = 0, g = 0, b = 0, alpha = 0;
};
DisplayPixel display_pixel(const double* rgba, const ToneMapping& tone);

// Step 4 on a picture: CV_8U/16U/32F with 3 (BGR over the background) or 4 (BGRA) channels.
cv::Mat display(const FlameHistogram& pixels, const ToneMapping& tone, int channels, int depth,
                int threads);

}  // namespace ifsfx::flame
