// SPDX-License-Identifier: Apache-2.0
// Presets from Python: the class Ifs (an IfsPreset: the IFS and where it came from),
// load_preset(), presets(), and an IFS built from an (N, 6) array of a..f.
#pragma once

#include <pybind11/pybind11.h>

#include "ifs/preset.h"

namespace ifsfx::python {

namespace py = pybind11;

void bind_presets(py::module_& m);

// A preset argument: an Ifs object, or a spec load_preset takes (a shipped name, a .toml or .ifs
// path, FILE.ifs:NAME). An unknown bare name is a ValueError, a missing file a FileNotFoundError.
IfsPreset preset_arg(const py::handle& preset, bool allow_expansive = false);

}  // namespace ifsfx::python
