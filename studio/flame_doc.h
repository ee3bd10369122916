// SPDX-License-Identifier: Apache-2.0
// A fractal flame in the studio (docs/studio.md, "Flames"): the page's JSON document of a flame
// and back, and the rectangle its camera shows. The page draws and drags each xform's pre-affine
// map as it drags an IFS's maps, in the *editor plane*: the flame plane turned as the camera
// turns it and flipped to y up (the flame plane's y points down the picture, flame/flame.h), so
// that each triangle lies over the picture where its points land. The rest travels as the file
// says it; the server keeps none of it (the page sends the whole flame with every request).
//
// The document (GET /api/preset?file=F.flame&entry=E, POST /api/render, POST /api/save):
//   {"name", "maps": [[a, b, c, d, e, f], ...],  // each xform's pre-affine map, editor plane
//    "flame": {"xforms": [XFORM, ...],            // one per map
//              "final": XFORM and "coefs": [6] | null,
//              "camera": {"size": [w, h], "center": [x, y], "scale", "zoom", "rotate", "zpos",
//                         "perspective", "yaw", "pitch", "depth_blur"},
//              "palette": {"colours": [[r, g, b, a] x 256], "source": "inline" | "library",
//                          "index", "hue", "mode": "step" | "linear"},
//              "tone": {"brightness", "gamma", "gamma_threshold", "vibrancy", "highlight_power",
//                       "contrast", "background": [r, g, b, a]},
//              "filtering": {"supersample", "filter_radius", "filter_shape", "estimator_radius",
//                            "estimator_minimum", "estimator_curve"},
//              "quality"}}
//   XFORM: {"name", "weight", "colour", "colour_speed", "opacity", "chaos": [...], "post": [6] |
//           null, "variations": [TERM...], "pre_variations": [...], "post_variations": [...]}
//   TERM:  {"name": "julian", "weight": 0.5, "params": {"julian_power": 3, "julian_dist": 1}}
// "maps" are in the editor's order (x' = a·x + b·y + e, y' = c·x + d·y + f); "post" and the final
// xform's "coefs" in the file's (flam3's a b c d e f, flame plane). Colours are in [0, 1]. Every
// field of "flame" but "xforms" may be left out (flame/flame.h's defaults), as may a term's
// parameters (the registry's defaults).
//
//   const StudioFlame f = flame_from_json(json::parse(request.body));
//   write_file(output, f.xml);   // what renders is what is saved
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "flame/flame.h"
#include "ifs/view.h"

namespace ifsfx::app {

// The document of `flame` for the page (the fields above, and "description": "", "warnings":
// [] as a preset has them).
nlohmann::json flame_to_json(const flame::Flame& flame);

// The flame of a request's document. It is written as flame XML and read back by the flame
// reader (flame/flame_file.h), so that a bad value gets the reader's message and what renders
// is exactly what Save writes (an inline palette as 8-bit hex; a library palette keeps its
// number and hue, and the colours the page sent, which the library gave). Throws Error{parse}
// naming the field for a value of the wrong type or shape ("flame.xforms[2].variations[0]:
// weight: must be a finite number (got \"x\")"), an unknown variation or parameter, more maps
// than kMaxMaps or not one xform per map, and what the reader throws.
struct StudioFlame {
  flame::Flame flame;
  std::string xml;  // flame_xml(flame): the file Save writes
};
StudioFlame flame_from_json(const nlohmann::json& body);

// The camera that shows `view` (a rectangle of the editor plane) on a picture of `size`, the
// flame's rotate and zoom kept (the scale follows the view's width); without a view, the flame's
// own framing at `size`, the scale following the width as render_flame resizes a flame.
flame::Camera studio_camera(const flame::Camera& camera, cv::Size size,
                            const std::optional<Box>& view);

// The rectangle of the editor plane a camera shows.
Box camera_view(const flame::Camera& camera);

// The variations for the page's menus: [{"name", "params": [{"name", "default"}], "pre_only"}],
// the registry's order (flame/variations.h).
nlohmann::json variations_json();

}  // namespace ifsfx::app
