// SPDX-License-Identifier: Apache-2.0
// Steal maps from Python: compute (steal_map), save and load, and apply to any image array.
#pragma once

#include <pybind11/pybind11.h>

namespace ifsfx::python {

namespace py = pybind11;

void bind_steal(py::module_& m);

}  // namespace ifsfx::python
