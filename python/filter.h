// SPDX-License-Identifier: Apache-2.0
// The video filter frame by frame from Python: ifsfx.Filter, one FractalEngine (the engine of
// `ifsfx filter`, `ifsfx cam` and the frei0r plugins) fed with frames from cv2 or PyAV.
#pragma once

#include <pybind11/pybind11.h>

namespace ifsfx::python {

namespace py = pybind11;

void bind_filter(py::module_& m);

}  // namespace ifsfx::python
