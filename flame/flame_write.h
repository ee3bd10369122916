// SPDX-License-Identifier: Apache-2.0
// Flames written as flame XML that flam3-render, Apophysis and Fractorium open (flam3 3.1's
// attribute names; docs/flames.md), and any affine IFS as a flame.
//
//   const Flame f = flame_from_ifs(load_ifs("barnsley-fern").ifs, {.size = {800, 600}});
//   output.write(flame_xml(f));
#pragma once

#include <span>
#include <string>

#include <opencv2/core.hpp>

#include "flame/flame.h"
#include "ifs/ifs.h"
#include "ifs/sampling.h"

namespace ifsfx::flame {

// The XML of one flame (a bare <flame> element) or of several (in <flames>), numbers written
// with as many digits as reading them back needs (read, write, read gives equal flames). A
// palette read from flam3's library is written as palette="N" hue="h", any other one inline
// (RGB hex, RGBA when an entry is not opaque). Throws Error{invalid_argument} for what a flame
// file cannot hold: the same variation twice in one list of an xform, a parameter count that is
// not the variation's.
std::string flame_xml(const Flame& flame);
std::string flames_xml(std::span<const Flame> flames);

struct FlameFromIfsOptions {
  cv::Size size{512, 512};  // the flame's picture, pixels
  // The framing: sampling.view, or the attractor auto-framed with sampling.margin, exactly as
  // ifsfx renders it (framed_viewport); sampling.quality becomes the flame's quality.
  Sampling sampling;
  double brightness = 4;  // ifsfx's measure defaults (docs/design.md §4)
  double gamma = 2.2;
};

// An affine IFS as a flame that draws its measure as ifsfx does (docs/design.md §4): one xform
// per map, its affine map conjugated by the flip y ↦ −y (the flame plane has y down), linear
// variation, the map's probability as its weight, colour n/(N−1) with speed 1/2 (ifsfx's palette
// coordinate c_k = (c_{k−1} + c_σk)/2), the palette the IFS's colours (or ifsfx's ramp) sampled
// at 256 points, and the camera framing the same rectangle. Named after the IFS.
Flame flame_from_ifs(const Ifs& ifs, const FlameFromIfsOptions& options = {});

}  // namespace ifsfx::flame
