// SPDX-License-Identifier: Apache-2.0
// How a picture of an IFS is sampled, one struct for every picture the libraries make (render,
// tops, steal maps, the video filter, the Python module): which rectangle of the plane is shown,
// how densely the chaos game covers it, from which seed, on how many threads, and when to stop.
// Options types hold it as their `sampling` member, so that a caller passes one value from
// layer to layer instead of copying fields (OpenImageIO's uniform (ROI, nthreads) is the model).
//   RenderOptions o{.sampling = {.quality = 128, .seed = 7}, .gamma = 2.0};
#pragma once

#include <cstdint>
#include <optional>

#include "ifs/cancel.h"
#include "ifs/ifs.h"
#include "ifs/view.h"

namespace ifsfx {

struct Sampling {
  std::optional<Box> view;  // the plane rectangle shown; default: the attractor, auto-framed
  double margin = 0.05;     // auto-framing margin, a fraction of the attractor's larger side
  double quality = 64;      // chaos-game points per output pixel (the exact descent's attractor
                            // mask takes its own, see StealMapStats)
  std::uint64_t seed = 1;   // seeds every random choice; equal seeds give equal bytes
  int threads = 0;          // 0 = all cores; the bytes never depend on it (docs/design.md §7)
  CancelToken cancel;       // polled between chunks of work: Error{interrupted} on a stop request

  friend bool operator==(const Sampling&, const Sampling&) = default;
};

// The raster every picture of `ifs` is drawn on: sampling.view, or the attractor auto-framed
// with sampling.margin (attractor_bounds seeded by sampling.seed, polling sampling.cancel).
Viewport framed_viewport(const Ifs& ifs, cv::Size size, const Sampling& sampling);

}  // namespace ifsfx
