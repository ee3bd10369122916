// SPDX-License-Identifier: Apache-2.0
// The picture of `ifsfx render`'s four modes, made by one function for the command and for
// `ifsfx studio` (its live picture and its still jobs), so that both doors give the same bytes
// (docs/design.md §10).
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "apps/steal_modes.h"
#include "ifs/ifs.h"
#include "ifs/output_file.h"
#include "ifs/render.h"

namespace ifsfx::app {

enum class RenderMode { attractor, measure, tops, steal };

// "attractor", "measure", "tops" or "steal".
const char* to_string(RenderMode mode) noexcept;
// The mode named `text`; throws Error{invalid_argument} naming `what` otherwise.
RenderMode parse_render_mode(const std::string& text, const std::string& what = "--mode");

struct PictureArgs {
  RenderMode mode = RenderMode::measure;
  bool second_symbol = false;  // tops: mix in the second symbol's colour
  // tops and steal: exact (descent or chaos game) and background; steal: the rest.
  StealModeArgs steal;
};

// The image `ifsfx render` writes to `output` (its format decides on alpha): render_attractor,
// render_measure, tops_image or steal_image by args.mode. A steal map to save (args.steal.save_map)
// is added to `staged`. Throws what those throw (Error{interrupted} when options.cancel asks).
//   RenderStats stats;
//   cv::Mat image = render_picture(F, {512, 512}, {}, {.mode = RenderMode::tops}, "a.png", staged,
//                                  &stats);
cv::Mat render_picture(const Ifs& F, cv::Size size, const RenderOptions& options,
                       const PictureArgs& args, const std::string& output,
                       std::vector<OutputFile>& staged, RenderStats* stats);

}  // namespace ifsfx::app
