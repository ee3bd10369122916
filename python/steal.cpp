// SPDX-License-Identifier: Apache-2.0
#include "python/steal.h"

#include <memory>
#include <mutex>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/options.h"
#include "python/presets.h"

namespace ifsfx::python {

PreparedStealMapCache::Table PreparedStealMapCache::get(const StealMap& map, cv::Size source_size,
                                                        const ApplyOptions& options) {
  {
    const std::lock_guard lock(mutex_);
    if (table_ && table_->source_size == source_size &&
        table_->options.interpolation == options.interpolation &&
        table_->options.border == options.border &&
        table_->options.background == options.background &&
        table_->options.threads == options.threads)
      return table_;
  }
  // Built outside the lock: another thread may use the last table meanwhile.
  Table table = std::make_shared<const PreparedStealMap>(prepare_apply(map, source_size, options));
  const std::lock_guard lock(mutex_);
  table_ = table;
  return table;
}

namespace {

SharedStealMap compute(const py::object& preset, const py::object& size,
                       const py::object& colouring, const py::object& view, double margin,
                       bool exact, double quality, std::uint64_t seed, int threads,
                       bool allow_expansive) {
  const cv::Size pixels = size_arg(size);
  const RenderOptions d;
  const Keywords k =
      keywords(view, margin, quality, d.supersample, d.gamma, d.brightness, seed, threads, exact);
  const IfsPreset F = preset_arg(preset, allow_expansive);
  const Ifs G = load_colouring(colouring.is_none() ? std::string() : colouring.cast<std::string>(),
                               F.ifs, "colouring");
  return SharedStealMap(run_released([&](const CancelToken& cancel) {
    return compute_steal_map(F.ifs, G, pixels, steal_map_options(k, cancel));
  }));
}

// The one-shot apply's check of the image, before any table is made for its size (so that an
// empty or unsupported image gets its message, not the table's).
void check_apply_image(const cv::Mat& source) {
  PreparedStealMap any_table;
  any_table.source_size = source.size();
  check_apply_source(any_table, source);
}

// apply() of `ifsfx apply`: the map's pixels coloured from `image`, the image's dtype and
// channels, `background` where the map is not covered. The remap table is the object's cached
// one when the image has the size and the options of the last call (the bytes of the one-shot
// apply(map, source, options) either way).
py::array apply_map(const SharedStealMap& shared, const py::object& image,
                    const py::object& background, const std::string& interpolation, int threads,
                    bool rgb) {
  const MatView view = to_mat(image, "image");
  const cv::Mat source = swap_red_blue(view.mat, rgb);
  const ApplyOptions options{
      .interpolation = interpolation_arg(interpolation),
      .background = background_scalar(colour_arg(background), source.depth()),
      .threads = threads};
  return to_array(swap_red_blue(run_released([&](const CancelToken&) {
                                  check_apply_image(source);
                                  cv::Mat out;
                                  apply(*shared.cache->get(*shared.map, source.size(), options),
                                        source, out);
                                  return out;
                                }),
                                rgb));
}

}  // namespace

void bind_steal(py::module_& m) {
  py::class_<SharedStealMap>(m, "StealMap", R"doc(
The steal map of colour stealing: per output pixel, the source coordinate T(x) (normalised
image coordinates, u right, v down) and whether the pixel lies on the attractor. Computed once,
it colours any number of images or frames by one remap each:

    T = ifsfx.steal_map("barnsley-fern", size=(640, 480))
    for frame in frames: out = T.apply(frame)
)doc")
      .def_property_readonly(
          "source_uv", [](const SharedStealMap& s) { return to_array(s.map->source_uv.clone()); },
          "H×W×2 float32: (u, v) per output pixel (a copy)")
      .def_property_readonly(
          "coverage", [](const SharedStealMap& s) { return to_array(s.map->coverage.clone()); },
          "H×W uint8: 255 where the pixel lies on the attractor (a copy)")
      .def_property_readonly(
          "size",
          [](const SharedStealMap& s) {
            return py::make_tuple(s.map->size().width, s.map->size().height);
          },
          "(width, height)")
      .def(
          "apply", &apply_map, py::arg("image"), py::kw_only(), py::arg("background") = "black",
          py::arg("interpolation") = "bilinear", py::arg("threads") = ApplyOptions{}.threads,
          py::arg("rgb") = false,
          R"doc(The map's pixels coloured from `image` (any size; H×W×C uint8, uint16 or float32, BGR like
cv2): an array of the map's size and the image's dtype and channels, `background` ("black",
"white", "#rrggbb" or (R, G, B)) off the attractor, as `ifsfx apply MAP IMAGE -o OUT.jpg`.
interpolation: "bilinear" (default) or "nearest". threads: default 0 = all cores.
rgb: False (default): BGR(A) in and out, like cv2; True: RGB(A).)doc")
      .def(
          "save",
          [](const SharedStealMap& s, const std::string& path) {
            run_released([&](const CancelToken& cancel) {
              save(*s.map, path, {.cancel = cancel});
              return 0;
            });
          },
          py::arg("path"),
          "save(path): the map as a versioned binary file (`ifsfx apply` reads it), written "
          "through a temporary file renamed into place")
      .def("__repr__", [](const SharedStealMap& s) {
        return fmt::format("<ifsfx.StealMap {}x{}>", s.map->size().width, s.map->size().height);
      });

  const StealMapOptions defaults;
  const Sampling& d = defaults.sampling;
  m.def(
      "steal_map", &compute, py::arg("preset"), py::kw_only(),
      py::arg("size") = py::make_tuple(1024, 1024), py::arg("colouring") = py::none(),
      py::arg("view") = py::none(), py::arg("margin") = d.margin, py::arg("exact") = defaults.exact,
      py::arg("quality") = d.quality, py::arg("seed") = d.seed, py::arg("threads") = d.threads,
      py::arg("allow_expansive") = false,
      R"doc(The steal map of `preset` (drawing IFS F) through `colouring` (a preset with as many maps,
default None: a tiling of the source), as `ifsfx render --mode steal --save-map` computes it.
exact: the exact per-pixel descent (default) or the chaos game (False, `quality` points per
pixel). The GIL is released; Ctrl-C stops it.)doc");
  m.def(
      "load_steal_map",
      [](const std::string& path) {
        return SharedStealMap(
            run_released([&](const CancelToken&) { return load_steal_map(path); }));
      },
      py::arg("path"),
      R"doc(A map saved by StealMap.save() or `ifsfx render --save-map`. Raises FileNotFoundError, or
OSError/ValueError for a file that is not a steal map.)doc");
  m.def("apply", &apply_map, py::arg("map"), py::arg("image"), py::kw_only(),
        py::arg("background") = "black", py::arg("interpolation") = "bilinear",
        py::arg("threads") = ApplyOptions{}.threads, py::arg("rgb") = false,
        R"doc(map.apply(image, ...): see StealMap.apply.)doc");
}

}  // namespace ifsfx::python
