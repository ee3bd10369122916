// SPDX-License-Identifier: Apache-2.0
#include "python/fit.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <opencv2/core.hpp>

#include "collage/fit.h"
#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "run/fit_run.h"

namespace ifsfx::python {
namespace {

collage::Initialisation init_arg(const std::string& init) {
  if (init == "search") return collage::Initialisation::search;
  if (init == "moments") return collage::Initialisation::moments;
  throw Error(ErrorKind::invalid_argument, fmt::format("init: search or moments (got '{}')", init));
}

// size=: S (an int) or "S" / "SxS", as --size.
std::string working_size_arg(const py::object& size) {
  if (py::isinstance<py::bool_>(size) ||
      !(py::isinstance<py::int_>(size) || py::isinstance<py::str>(size)))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("size: the working raster is S or \"SxS\" (got {})",
                            std::string(py::repr(size))));
  return py::isinstance<py::str>(size) ? size.cast<std::string>()
                                       : std::to_string(size.cast<long long>());
}

// An array target as the command reads a picture: its alpha, else its dark pixels; a bool array
// is the mask itself (True: the shape), read as a black shape on white.
cv::Mat array_shape(const py::object& target, const collage::TargetOptions& options, bool rgb) {
  py::object image = target;
  if (py::isinstance<py::array>(target) &&
      py::array(target.cast<py::array>()).dtype().equal(py::dtype::of<bool>())) {
    const py::module_ np = py::module_::import("numpy");
    image = np.attr("where")(target, 0, 255).attr("astype")("uint8");
  }
  const MatView view = to_mat(image, "target");
  return collage::shape_mask(swap_red_blue(view.mat, rgb), options, "target");
}

IfsPreset fit(const py::object& target, int maps, std::uint64_t seed, const std::string& init,
              std::optional<double> threshold, bool invert, const py::object& size,
              double max_seconds, long max_evaluations, double reseed_share, double grow_share,
              int threads, const std::optional<std::string>& name, bool rgb) {
  app::FitArgs args;
  const bool is_path = py::isinstance<py::str>(target) || py::hasattr(target, "__fspath__");
  args.maps = maps;
  args.seed = seed;
  args.init = init_arg(init);
  args.threshold = threshold;
  args.invert = invert;
  args.size = working_size_arg(size);
  args.max_seconds = max_seconds;
  args.max_evaluations = max_evaluations;
  args.reseed_share = reseed_share;
  args.grow_share = grow_share;
  args.threads = threads;
  app::check_fit_maps(args.maps, "n");
  app::check_fit_budgets(max_seconds, max_evaluations,
                         {.seconds = "max_seconds", .evaluations = "max_evaluations"});
  app::check_fit_shares(reseed_share, grow_share, {.reseed = "reseed_share", .grow = "grow_share"});
  cv::Mat shape;
  if (is_path) {
    args.target = py::isinstance<py::str>(target)
                      ? target.cast<std::string>()
                      : py::str(target.attr("__fspath__")()).cast<std::string>();
  } else {
    shape = array_shape(target, {.threshold = threshold, .invert = invert}, rgb);
    args.target = fmt::format("array {}x{}", shape.cols, shape.rows);
  }
  IfsPreset preset;
  preset.ifs = run_released([&](const CancelToken& cancel) {
    const cv::Mat raster =
        is_path ? app::fit_raster(args)
                : collage::working_raster(shape, {.size = app::working_size(args.size)});
    collage::FitOptions options = app::fit_options(args, cancel);
    options.fine_target =
        is_path ? app::fit_fine_raster(args)
                : collage::working_raster(
                      shape, {.size = std::min(4 * app::working_size(args.size), 2048)});
    if (!is_path) options.name = "fitted";
    if (name) options.name = *name;
    const collage::FitResult result = collage::fit(raster, options);
    // A stop raises KeyboardInterrupt in Python, as before (the command keeps the best so far).
    if (result.interrupted) throw Error(ErrorKind::interrupted, "fit: interrupted");
    preset.description = app::fit_summary(args, result);
    return result.ifs;
  });
  preset.origin = args.target;
  preset.text = to_toml(preset.ifs, preset.description);
  return preset;
}

}  // namespace

void bind_fit(py::module_& m) {
  const app::FitArgs d;
  m.def("fit", &fit, py::arg("target"), py::arg("n") = d.maps, py::kw_only(),
        py::arg("seed") = d.seed, py::arg("init") = "search", py::arg("threshold") = py::none(),
        py::arg("invert") = d.invert, py::arg("size") = std::stoi(d.size),
        py::arg("max_seconds") = d.max_seconds, py::arg("max_evaluations") = d.max_evaluations,
        py::arg("reseed_share") = d.reseed_share, py::arg("grow_share") = d.grow_share,
        py::arg("threads") = d.threads, py::arg("name") = py::none(), py::arg("rgb") = false,
        R"doc(An IFS of `n` maps whose attractor looks like the target's shape, found by the collage
theorem, as `ifsfx fit TARGET -n N -o OUT.toml` finds it: for a path, `.to_toml()` is the file
the command writes, byte for byte (same target, options and seed). The GIL is released while
it works; Ctrl-C stops it (KeyboardInterrupt).

target: an image path, or an array read as the command reads a picture (H×W or H×W×C of
    uint8, uint16 or float32, BGR like cv2): the shape is its alpha channel where it has one,
    else its dark pixels; a bool H×W array is the mask itself (True on the shape).
n: the number of affine maps, 1..32, default 4.
seed: default 1; with max_seconds=0 the same seed gives the same maps on any machine.
init: "search" (default: fractal-compression range/domain search) or "moments" (faster, for
    convex, nearly self-similar shapes).
threshold: grey (or alpha) level in [0, 1] between shape and background, default None: Otsu
    (alpha: 0.5).
invert: swap shape and background (a light shape, a clear alpha), default False.
size: the working raster's side S (or "SxS"), default 128.
max_seconds: wall-clock cap of the search, default 30; 0: none.
max_evaluations: objective evaluations over all runs, default 250000.
reseed_share: the share of the attractor's stages spent re-seeding the maps that pay least onto
    the parts the attractor misses, in [0, 0.15], default 0.15; 0: none.
grow_share: the share of the attractor's stages spent growing from fewer maps (the two that pay
    least dropped, then maps added one at a time where the attractor misses most), in [0, 0.15],
    default 0; 0: none.
threads: default 0 = all cores.
name: the IFS's name, default None: the path's stem, or "fitted" for an array.
rgb: an array target in RGB(A) order, default False (BGR(A), like cv2).

The Ifs's description carries the fit's IoU and contraction, as the command's preset does.
Raises ValueError for bad options or an empty/full shape, FileNotFoundError/OSError for files.)doc");
}

}  // namespace ifsfx::python
