// SPDX-License-Identifier: Apache-2.0
// What `ifsfx studio` renders: the page's JSON turned into the options `ifsfx render` takes, and
// the PNG `ifsfx render` would write for them (same library calls, same options, same bytes). The
// server keeps no mathematics of its own: the page sends the whole preset with every request.
//
// A request (POST /api/render, docs/studio.md):
//   {"name": "fern", "maps": [[a, b, c, d, e, f], ...], "probabilities": [...],   // optional
//    "colours": ["#rrggbb", ...],                                                 // optional
//    "mode": "attractor" | "measure" | "tops" | "steal", "size": "768x768",
//    "source": "sample" | FILE,  // steal mode: the shipped sample or a file of --folder
//    "view": "x0,y0,x1,y1",      // optional: the plane rectangle shown (default: auto-framed)
//    "seed": 1, "quality": 64, "exact": true}                                     // optional
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/preset.h"
#include "ifs/render.h"

namespace ifsfx::app {

// The preset of a request: name, description, maps, probabilities and colours. Its text is the
// TOML that `to_toml` writes, so a saved preset renders with the same metadata. Throws
// Error{parse} for a field of the wrong type or shape, and what validate() throws for an IFS that
// does not contract (or contract on average with "allow_expansive": true).
IfsPreset preset_from_json(const nlohmann::json& body);

// The preset as the page reads it (the fields above).
nlohmann::json preset_to_json(const IfsPreset& preset);

// Everything one render needs, in the library's terms.
struct StudioRender {
  IfsPreset preset;
  cv::Size size{768, 768};
  std::string mode = "tops";     // attractor, measure, tops or steal
  RenderOptions options;         // `ifsfx render`'s defaults but for what the request sets
  bool exact = true;             // tops/steal: exact descent (--exact) or the chaos game (--chaos)
  std::filesystem::path source;  // steal mode: the source image
};

// The one place where the page's settings become library options. `source_path` turns the request's
// "source" into a readable file or throws Error{invalid_argument}. Throws Error{parse} or
// Error{invalid_argument} for a bad field, naming it.
StudioRender studio_render_from_json(
    const nlohmann::json& body,
    const std::function<std::filesystem::path(const std::string&)>& source_path);

struct StudioPicture {
  std::string png;  // the file's bytes
  Box view;         // the plane rectangle shown
};

// The PNG bytes of `ifsfx render PRESET --mode MODE --size WxH --seed S --quality Q [--view V]`
// (the steal mode with --source), written through a temporary file in `scratch` that is removed
// before returning. Throws Error{interrupted} when `cancel` asks to stop, and what render throws.
StudioPicture render_png(const StudioRender& render, CancelToken cancel,
                         const std::filesystem::path& scratch);

}  // namespace ifsfx::app
