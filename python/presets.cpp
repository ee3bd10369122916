// SPDX-License-Identifier: Apache-2.0
#include "python/presets.h"

#include <array>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "flame/flame_file.h"
#include "flame/flame_write.h"
#include "ifs/error.h"

namespace ifsfx::python {
namespace {

// A spec that names a file: a path, a .toml/.ifs file, or FILE.ifs:NAME.
bool names_a_file(const std::string& spec) {
  return spec.find('/') != std::string::npos || spec.find(':') != std::string::npos ||
         spec.ends_with(".toml") || spec.ends_with(".ifs");
}

// load_ifs with its warnings given to Python's warnings module.
IfsPreset load(const std::string& spec, bool allow_expansive) {
  IfsPreset preset;
  try {
    preset = load_ifs(spec, {.allow_expansive = allow_expansive});
  } catch (const Error& e) {
    // An unknown shipped name is bad input, not a missing file.
    if (e.kind() == ErrorKind::not_found && !names_a_file(spec))
      throw Error(ErrorKind::invalid_argument, e.what());
    throw;
  }
  for (const std::string& warning : preset.warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  return preset;
}

// An IFS from an (N, 6) array of a b c d e f, validated as a preset file is.
IfsPreset from_arrays(const py::array_t<double, py::array::c_style | py::array::forcecast>& maps,
                      const std::optional<std::vector<double>>& probabilities,
                      const std::string& name, bool allow_expansive) {
  if (maps.ndim() != 2 || maps.shape(1) != 6 || maps.shape(0) < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("maps: an (N, 6) array of a, b, c, d, e, f (got shape {})",
                            std::string(py::str(py::cast(std::vector<py::ssize_t>(
                                maps.shape(), maps.shape() + maps.ndim()))))));
  IfsPreset preset;
  preset.ifs.name = name;
  const auto k = maps.unchecked<2>();
  for (py::ssize_t n = 0; n < maps.shape(0); ++n)
    preset.ifs.maps.push_back(
        AffineMap::from_coefficients({k(n, 0), k(n, 1), k(n, 2), k(n, 3), k(n, 4), k(n, 5)}));
  if (probabilities) preset.ifs.probabilities = *probabilities;
  preset.origin = "array";
  preset.allow_expansive = allow_expansive;
  validate(preset.ifs, name.empty() ? "ifs" : name, {.allow_expansive = allow_expansive});
  preset.text = to_toml(preset.ifs);
  return preset;
}

py::array_t<double> maps_array(const Ifs& ifs) {
  py::array_t<double> out({static_cast<py::ssize_t>(ifs.size()), py::ssize_t{6}});
  auto k = out.mutable_unchecked<2>();
  for (std::size_t n = 0; n < ifs.size(); ++n) {
    const auto c = ifs.maps[n].coefficients();
    for (py::ssize_t i = 0; i < 6; ++i) k(static_cast<py::ssize_t>(n), i) = c[i];
  }
  return out;
}

}  // namespace

IfsPreset preset_arg(const py::handle& preset, bool allow_expansive) {
  if (py::isinstance<IfsPreset>(preset)) return preset.cast<IfsPreset>();
  if (py::isinstance<py::str>(preset)) return load(preset.cast<std::string>(), allow_expansive);
  // os.PathLike
  if (py::hasattr(preset, "__fspath__"))
    return load(py::str(preset.attr("__fspath__")()).cast<std::string>(), allow_expansive);
  throw Error(ErrorKind::invalid_argument,
              fmt::format("preset: a name, a path or an ifsfx.Ifs (got {})",
                          std::string(py::str(py::type::of(preset).attr("__name__")))));
}

engine::Drawing drawing_arg(const py::handle& preset, bool allow_expansive) {
  if (py::isinstance<flame::Flame>(preset)) return preset.cast<flame::Flame>();
  std::string spec;
  if (py::isinstance<py::str>(preset)) spec = preset.cast<std::string>();
  if (py::hasattr(preset, "__fspath__")) spec = py::str(preset.attr("__fspath__")());
  if (!spec.empty() && flame::is_flame_spec(spec)) return flame::read_flame(spec);
  return preset_arg(preset, allow_expansive).ifs;
}

namespace {

// ifsfx.Flame: what Python sees of a flame.
void bind_flame(py::module_& m) {
  py::class_<flame::Flame>(m, "Flame", R"doc(
A fractal flame of flam3, Apophysis, JWildfire or Fractorium, read by load_preset("art.flame:NAME").
render() draws its measure as flam3 does and its attractor, tops and colour stealing through the
chaos game (its xforms play the maps' part); Filter takes it as its preset.
)doc")
      .def_property_readonly("name", [](const flame::Flame& f) { return f.name; })
      .def_property_readonly(
          "size", [](const flame::Flame& f) { return std::pair(f.camera.width, f.camera.height); },
          "the camera's (width, height) in pixels")
      .def_property_readonly(
          "text", [](const flame::Flame& f) { return flame::flame_xml(f); },
          "the flame as flam3 XML")
      .def("__len__", [](const flame::Flame& f) { return f.xforms.size(); })
      .def("__repr__", [](const flame::Flame& f) {
        return fmt::format("<ifsfx.Flame '{}': {} xforms{}>", f.name, f.xforms.size(),
                           f.final_xform ? " and a final xform" : "");
      });
}

}  // namespace

void bind_presets(py::module_& m) {
  bind_flame(m);
  py::class_<IfsPreset>(m, "Ifs", R"doc(
An iterated function system: affine maps f(x, y) = (a x + b y + e, c x + d y + f) with
probabilities, and where it came from. Made by load_preset() or from an (N, 6) array:

    fern = ifsfx.load_preset("barnsley-fern")
    tri = ifsfx.Ifs([[.5, 0, 0, .5, 0, 0], [.5, 0, 0, .5, .5, 0], [.5, 0, 0, .5, .25, .5]])
)doc")
      .def(py::init(&from_arrays), py::arg("maps"), py::arg("probabilities") = py::none(),
           py::arg("name") = "", py::arg("allow_expansive") = false,
           R"doc(maps: (N, 6) array of a, b, c, d, e, f per map (Barnsley's and Fractint's order).
probabilities: N weights (normalised), default None: proportional to |det| with a floor.
allow_expansive: default False; True accepts maps of factor >= 1 when the IFS contracts
on average. Raises ValueError for maps that do not contract, bad probabilities, NaN.)doc")
      .def_property_readonly("name", [](const IfsPreset& p) { return p.ifs.name; })
      .def_property_readonly(
          "maps", [](const IfsPreset& p) { return maps_array(p.ifs); },
          "(N, 6) float64 array of a, b, c, d, e, f per map (a copy)")
      .def_property_readonly(
          "probabilities", [](const IfsPreset& p) { return effective_probabilities(p.ifs); },
          "the probabilities the chaos game draws with (normalised, or the defaults)")
      .def_property_readonly(
          "colours",
          [](const IfsPreset& p) {
            std::vector<std::array<double, 3>> out;
            for (const Rgb& c : p.ifs.colours) out.push_back({c.r, c.g, c.b});
            return out;
          },
          "the preset's colour per map as (r, g, b) in [0, 1], or [] for the palette")
      .def_property_readonly("description", [](const IfsPreset& p) { return p.description; })
      .def_property_readonly(
          "origin", [](const IfsPreset& p) { return p.origin; },
          "where it came from: 'shipped:NAME.toml', a path, 'FILE.ifs:NAME'")
      .def_property_readonly(
          "text", [](const IfsPreset& p) { return p.text; },
          "the preset's own text (TOML, or the Fractint entry)")
      .def_property_readonly(
          "contraction", [](const IfsPreset& p) { return p.ifs.contraction(); },
          "the largest contraction factor of its maps")
      .def(
          "to_toml", [](const IfsPreset& p) { return to_toml(p.ifs, p.description); },
          "the IFS as a native TOML preset")
      .def("__len__", [](const IfsPreset& p) { return p.ifs.size(); })
      .def("__repr__", [](const IfsPreset& p) {
        return fmt::format("<ifsfx.Ifs '{}': {} maps from {}>", p.ifs.name, p.ifs.size(), p.origin);
      });

  m.def(
      "load_preset",
      [](const std::string& spec, bool allow_expansive) -> py::object {
        if (flame::is_flame_spec(spec)) return py::cast(flame::read_flame(spec));
        return py::cast(load(spec, allow_expansive));
      },
      py::arg("spec"), py::arg("allow_expansive") = false,
      R"doc(A shipped name ("barnsley-fern", see presets()), a .toml or .ifs path, "FILE.ifs:NAME"
for one entry of a Fractint file, or a flame: "art.flame", "art.flame:NAME" or "art.flame:INDEX"
(an ifsfx.Flame). Raises ValueError for an unknown name or a malformed preset
(the message names the file and line), FileNotFoundError for a missing file. A Fractint entry
that contracts only on average is accepted with a UserWarning.)doc");
  m.def(
      "presets",
      [] {
        std::vector<std::string> names;
        for (const PresetSummary& p : list_shipped_presets()) names.push_back(p.name);
        return names;
      },
      R"doc(The names of the shipped IFS presets, as `ifsfx presets` lists them.)doc");
}

}  // namespace ifsfx::python
