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
//    "colouring": [[a, b, c, d, e, f], ...],  // steal mode, optional: G on the source's unit
//                                // square (default: the tiling default_colouring(N))
//    "view": "x0,y0,x1,y1",      // optional: the plane rectangle shown (default: auto-framed)
//    "seed": 1, "quality": 64, "exact": true, "threads": 0,                       // optional
//    "format": "png" | "rgba"}   // the file's bytes (default), or raw pixels for the live view
// or, for a fractal flame, its document (studio/flame_doc.h: "maps" and "flame") with "mode":
// "measure" (the flame look), "size", "view", "seed", "quality" (default: the flame's), "threads"
// and "format".
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "engine/drawing.h"
#include "ifs/cancel.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "run/render_modes.h"
#include "studio/flame_doc.h"

namespace ifsfx::app {

// The most maps an IFS of the page may have (a preset, an IFS of a superIFS, the defaults asked
// for): more than a hand edits, few enough that a request stays small.
inline constexpr std::size_t kMaxMaps = 64;

// The preset of a request: name, description, maps, probabilities and colours. Its text is the
// TOML that `to_toml` writes, so a saved preset renders with the same metadata. Throws
// Error{parse} for a field of the wrong type or shape, and what validate() throws for an IFS that
// does not contract (or contract on average with "allow_expansive": true); Error{unsupported} for
// a flame's document (it has "flame": only the editor's render and save take flames).
IfsPreset preset_from_json(const nlohmann::json& body);

// The maps of `ifs` as [[a, b, c, d, e, f], ...], and a colour as "#rrggbb".
nlohmann::json maps_to_json(const Ifs& ifs);
std::string hex_colour(const Rgb& colour);

// The preset as the page reads it (the fields above, "allow_expansive" and "warnings").
nlohmann::json preset_to_json(const IfsPreset& preset);

// The colouring IFS G of a request's "colouring" (null when absent or null): its maps, one per
// map of `F`, on the source's unit square, validated and fitted to the unit square as
// load_colouring fits a `--colouring` preset, so that the render is `ifsfx render --mode steal
// --colouring SAVED` of the same maps saved as TOML (colouring_preset). Throws Error{parse} for a
// badly shaped field and Error{invalid_ifs} for the wrong count or an IFS that does not contract
// on average.
std::optional<Ifs> colouring_from_json(const nlohmann::json& body, const Ifs& F);
// What a request draws as a filter or a preview: its flame ("flame", read as flame_from_json
// reads it) or its affine preset (preset_from_json); `text` gets the file text that tells one
// drawing from another (the preset's TOML or the flame's XML).
engine::Drawing drawing_from_json(const nlohmann::json& body, std::string* text = nullptr);

// The colouring IFS G of a request for `drawing`: one map per map of an IFS, per xform of a flame.
std::optional<Ifs> colouring_for_drawing(const nlohmann::json& body,
                                         const engine::Drawing& drawing);

// The same for `maps` maps, the count's rule naming what each map is for ("xform of the flame").
std::optional<Ifs> colouring_from_json(const nlohmann::json& body, std::size_t maps,
                                       const std::string& per);

// The colouring of a request as a preset of its own (the TOML that save writes beside the
// preset), named `name`; nullopt without one.
std::optional<IfsPreset> colouring_preset(const nlohmann::json& body, const std::string& name);

// How a picture travels: the PNG file `ifsfx render` writes, byte for byte, or its pixels as
// 8-bit RGBA rows top to bottom (straight alpha; converted as the PNG writer converts), which the
// page draws without decoding a file: the live view during a drag.
enum class PictureFormat { png, rgba };
// Everything one render needs, in the library's terms.
struct StudioRender {
  IfsPreset preset;
  cv::Size size{768, 768};
  RenderMode mode = RenderMode::tops;
  RenderOptions options;         // `ifsfx render`'s defaults but for what the request sets
  bool exact = true;             // tops/steal: exact descent (--exact) or the chaos game (--chaos);
                                 // a flame's default is the chaos game
  std::filesystem::path source;  // steal mode: the source image
  std::optional<Ifs> colouring;  // steal mode: G fitted to the unit square; none: the default
  PictureFormat format = PictureFormat::png;
  // A fractal flame instead of `preset` (the request had "flame"), rendered as `ifsfx render
  // FILE.flame --mode MODE` renders it at `size` — measure: the flame look (flame/render.h);
  // attractor, tops, steal: its xforms through the chaos game (flame/flame_chaos.h) — framed on
  // options.sampling.view when given; its quality is the request's when given.
  std::optional<StudioFlame> flame;
  int flame_depth = CV_8U;  // the flame's pixels: CV_8U, CV_16U or CV_32F (a still's file)
};

// The one place where the page's settings become library options. `source_path` turns the request's
// "source" into a readable file or throws Error{invalid_argument}. Throws Error{parse} or
// Error{invalid_argument} for a bad field, naming it.
StudioRender studio_render_from_json(
    const nlohmann::json& body,
    const std::function<std::filesystem::path(const std::string&)>& source_path);

// The picture of a request as `ifsfx render ... -o OUTPUT` makes it (`alpha`: whether OUTPUT's
// format keeps the coverage as alpha, run/picture_options.h's format_has_alpha) and the options
// that write it with the same metadata. Throws Error{interrupted} when `cancel` asks to stop, and
// what render throws.
struct StudioImage {
  cv::Mat image;
  WriteOptions write;  // the metadata `ifsfx render` stores
  Box view;            // the plane rectangle shown
};
StudioImage studio_image(const StudioRender& render, CancelToken cancel, bool alpha);

struct StudioPicture {
  std::string bytes;     // the PNG file, or the RGBA rows
  Box view;              // the plane rectangle shown
  double render_ms = 0;  // the library's render
  double encode_ms = 0;  // the PNG encoding or the RGBA conversion
};

// The picture of `ifsfx render PRESET --mode MODE --size WxH --seed S --quality Q [--view V]`
// (the steal mode with --source and --colouring): as PNG, the file's bytes (encoded in memory,
// the bytes `ifsfx render` writes); as RGBA, its pixels. Throws
// Error{interrupted} when `cancel` asks to stop, and what render throws.
StudioPicture render_picture(const StudioRender& render, CancelToken cancel);

// An image as 8-bit RGBA rows (grey, BGR or BGRA of any depth the library uses; converted to 8
// bits as write_image converts for an 8-bit PNG).
std::string rgba_bytes(const cv::Mat& image);

}  // namespace ifsfx::app
