// SPDX-License-Identifier: Apache-2.0
// The one place where Python keyword arguments become the library's options structs. Every
// binding that samples an IFS (render, steal_map) collects its keywords into Keywords and asks
// for the struct it calls with; the defaults shown in the docstrings are the library's own
// (read from RenderOptions{} and Sampling{}), so the two never drift apart.
#pragma once

#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <opencv2/core.hpp>

#include "engine/fractal_engine.h"
#include "ifs/cancel.h"
#include "ifs/ifs.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "ifs/view.h"

namespace ifsfx::python {

namespace py = pybind11;

// The keywords shared by the sampling entry points, as the CLI's `render` options.
struct Keywords {
  RenderOptions render;  // view=: None (auto-framed), (x0, y0, x1, y1) or "x0,y0,x1,y1"
  bool exact = StealMapOptions{}.exact;  // tops and steal: the exact descent, or the chaos game
};

// The keywords as Keywords; `view` is parsed and checked here.
Keywords keywords(const py::object& view, double margin, double quality, int supersample,
                  double gamma, double brightness, std::uint64_t seed, int threads, bool exact);

// The options each entry point takes, with the stop flag of run_released.
RenderOptions render_options(const Keywords& k, const CancelToken& cancel);
TopsOptions tops_options(const Keywords& k, const CancelToken& cancel);
StealMapOptions steal_map_options(const Keywords& k, const CancelToken& cancel);

// The keywords of ifsfx.Filter as the settings of its FractalEngine, as `ifsfx filter` fills them
// from its flags (defaults: FractalSettings{}); `view`, `background`, `interpolation` and
// `animate` are parsed here, the rest checked by the engine. Throws Error{invalid_argument}
// naming the keyword, as the command's rules (--loop needs an animation).
struct FilterKeywords {
  py::object preset, colouring, view, background, animate;
  std::string interpolation;
  double margin, quality, mix, drift_amount, drift_speed;
  py::object exact;  // None: the engine's default; True is refused for a flame
  std::uint64_t seed;
  int threads, keyframe_interval, buffers;
  std::string superifs;
  std::int64_t loop;
};
engine::FractalSettings fractal_settings(const FilterKeywords& k);

// interpolation=: "bilinear" or "nearest".
Interpolation interpolation_arg(const std::string& name);
// background= of the filter: "black", "white", "original", "#rrggbb", "R,G,B" or (R, G, B).
engine::Background filter_background_arg(const py::object& background);
// A preset, colouring or superIFS named by a str or an os.PathLike ("" for None).
std::string spec_arg(const py::object& spec, const std::string& what);

// size=: (width, height) or "WxH", 1..32768 a side (parse_size's checks and message).
cv::Size size_arg(const py::object& size, const std::string& what = "size");
// view=: None, a 4-sequence of numbers or "x0,y0,x1,y1".
std::optional<Box> view_arg(const py::object& view, const std::string& what = "view");
// background=: "black", "white", "#rrggbb" or (R, G, B) with 0..255, as the CLI's --background.
Rgb colour_arg(const py::object& colour, const std::string& what = "background");

}  // namespace ifsfx::python
