// SPDX-License-Identifier: Apache-2.0
// NumPy arrays and cv::Mat: images cross as H×W (one channel) or H×W×C arrays of uint8, uint16 or
// float32 (floats in [0, 1]), channels in OpenCV's order (BGR, BGRA), as cv2 hands them over.
#pragma once

#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <opencv2/core.hpp>

namespace ifsfx::python {

namespace py = pybind11;

// An array's pixels seen as a cv::Mat without a copy; `owner` keeps them alive (a contiguous copy
// when the array was not C-contiguous).
struct MatView {
  py::array owner;
  cv::Mat mat;
};

// `object` (an ndarray, or anything np.asarray reads) as an image: 2 dimensions, or 3 with 1 to 4
// channels; dtype uint8, uint16 or float32. Throws Error{invalid_argument} naming `what`:
// "source: an image is an H×W or H×W×C array (C = 1..4) of uint8, uint16 or float32 (got ...)".
MatView to_mat(const py::handle& object, const std::string& what);

// The Mat as an array that owns its pixels (shared with the Mat, no copy): H×W for one channel,
// H×W×C otherwise; CV_8U, CV_16U, CV_32F, CV_32S, CV_64F.
py::array to_array(cv::Mat mat);

// The image with its red and blue channels swapped (BGR <-> RGB, BGRA <-> RGBA) when `rgb` and
// it has 3 or 4 channels; else the image itself. The `rgb=True` keyword of the calls that take or
// give colour images.
cv::Mat swap_red_blue(const cv::Mat& image, bool rgb);

// The OpenCV depth for a dtype given as a NumPy dtype, a type (numpy.uint8) or a name ("uint8",
// "uint16", "float32"); None gives `fallback`. Throws Error{invalid_argument} naming "dtype".
int depth_of(const py::object& dtype, int fallback);

// The image at `depth`, scaled as write_image scales it for a file of that depth (255 for 8 bits,
// 65535 for 16, 1 for float), so that an array equals the pixels of the file the CLI writes.
cv::Mat to_depth(const cv::Mat& image, int depth);

}  // namespace ifsfx::python
