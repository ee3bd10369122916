// SPDX-License-Identifier: Apache-2.0
// ifsfx.render(): an IFS rendered to an array in every mode of `ifsfx render`, and the image
// files (read_image, write_image) the tests compare the command line's output with.
#pragma once

#include <string>

#include <pybind11/pybind11.h>
#include <opencv2/core.hpp>

namespace ifsfx::python {

namespace py = pybind11;

void bind_render(py::module_& m);

// A source argument: an image array (borrowed, no copy; its red and blue swapped with `rgb`) or a
// path read by read_image (BGR whatever `rgb` says).
cv::Mat source_arg(const py::handle& source, py::object& keep, const std::string& what,
                   bool rgb = false);

}  // namespace ifsfx::python
