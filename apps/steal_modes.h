// SPDX-License-Identifier: Apache-2.0
// The tops and steal modes of `ifsfx render`, and what they share with `ifsfx apply`: the
// --background colour, and making an image fit its output format (transparent background where
// the format has alpha, the background colour elsewhere).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/ifs.h"
#include "ifs/output_file.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"

namespace ifsfx::app {

// "black", "white", "#rrggbb" or "R,G,B" (0..255); throws Error{parse} naming `what`.
Rgb colour_option(const std::string& text, const std::string& what = "--background");

// True for outputs whose format keeps an alpha channel: .png, .tif, .tiff, .exr.
bool format_has_alpha(const std::string& path);

// The steal mode's own settings.
struct StealModeArgs {
  std::string source;     // image to steal colours from (any format OpenImageIO reads)
  std::string colouring;  // colouring IFS preset; empty: default_colouring(N)
  std::string save_map;   // also write the steal map here
  Rgb background;
  bool quiet = false;    // else print the coverage policy's figures on stdout
  OutputOptions output;  // the output policy of the saved map
};

// `--mode tops`: render_tops, the background made transparent or `background` for `output`.
cv::Mat tops_image(const Ifs& F, cv::Size size, const TopsOptions& options, const Rgb& background,
                   const std::string& output, RenderStats* stats);

// `--mode steal`: the steal map of F through G, applied to the source. With args.save_map, the
// map is written too and added to `staged`, to be put in place with the image (commit_together).
cv::Mat steal_image(const Ifs& F, cv::Size size, const StealMapOptions& options,
                    const StealModeArgs& args, const std::string& output,
                    std::vector<OutputFile>& staged, RenderStats* stats);

}  // namespace ifsfx::app
