// SPDX-License-Identifier: Apache-2.0
// Collage-theorem fitting from Python: fit(), the maps `ifsfx fit TARGET -n N -o OUT.toml`
// writes, for a target given as a path or as an array.
#pragma once

#include <pybind11/pybind11.h>

namespace ifsfx::python {

namespace py = pybind11;

void bind_fit(py::module_& m);

}  // namespace ifsfx::python
