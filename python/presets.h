// SPDX-License-Identifier: Apache-2.0
// Presets from Python: the class Ifs (an IfsPreset: the IFS and where it came from), the class
// Flame (a fractal flame of a flame file), load_preset(), presets(), and an IFS built from an
// (N, 6) array of a..f.
#pragma once

#include <pybind11/pybind11.h>

#include "engine/drawing.h"
#include "ifs/preset.h"

namespace ifsfx::python {

namespace py = pybind11;

void bind_presets(py::module_& m);

// A preset argument: an Ifs object, or a spec load_preset takes (a shipped name, a .toml or .ifs
// path, FILE.ifs:NAME). An unknown bare name is a ValueError, a missing file a FileNotFoundError.
IfsPreset preset_arg(const py::handle& preset, bool allow_expansive = false);

// A preset argument as the engine draws it: an ifsfx.Flame, or a flame spec (FILE.flame,
// FILE.flame:NAME or :INDEX) read as a flame; anything else as preset_arg reads it.
engine::Drawing drawing_arg(const py::handle& preset, bool allow_expansive = false);

}  // namespace ifsfx::python
