// SPDX-License-Identifier: Apache-2.0
// ifsfx.fractaldb: FractalDB's category and weight files, its category search, and its datasets
// as (image, label) pairs in memory, for a PyTorch-style DataLoader (docs/dataset.md).
#pragma once

#include <pybind11/pybind11.h>

namespace ifsfx::python {

namespace py = pybind11;

// Adds the submodule `fractaldb` to `m` (also importable as `import ifsfx.fractaldb`).
void bind_fractaldb(py::module_& m);

}  // namespace ifsfx::python
