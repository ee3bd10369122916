// SPDX-License-Identifier: Apache-2.0
// SuperIFS textures from Python: texture() for one, textures() for an iterator over a sequence,
// as `ifsfx texture` writes them.
#pragma once

#include <pybind11/pybind11.h>

namespace ifsfx::python {

namespace py = pybind11;

void bind_texture(py::module_& m);

}  // namespace ifsfx::python
