// SPDX-License-Identifier: Apache-2.0
#include "python/arrays.h"

#include <vector>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx::python {
namespace {

Error bad_image(const std::string& what, const std::string& got) {
  return Error(ErrorKind::invalid_argument,
               fmt::format("{}: an image is an H×W or H×W×C array (C = 1..4) of uint8, uint16 or "
                           "float32 (got {})",
                           what, got));
}

double full_scale(int depth) {
  return depth == CV_8U ? 255.0 : depth == CV_16U ? 65535.0 : 1.0;
}

}  // namespace

MatView to_mat(const py::handle& object, const std::string& what) {
  if (!py::isinstance<py::array>(object))
    throw bad_image(what, std::string(py::str(py::type::of(object).attr("__name__"))));
  py::array array = py::array::ensure(object, py::array::c_style);
  if (!array) throw py::error_already_set();
  const py::dtype dtype = array.dtype();
  int depth = -1;
  if (dtype.equal(py::dtype::of<std::uint8_t>()))
    depth = CV_8U;
  else if (dtype.equal(py::dtype::of<std::uint16_t>()))
    depth = CV_16U;
  else if (dtype.equal(py::dtype::of<float>()))
    depth = CV_32F;
  const auto ndim = array.ndim();
  const int channels = ndim == 3 ? static_cast<int>(array.shape(2)) : 1;
  if (depth < 0 || (ndim != 2 && ndim != 3) || channels < 1 || channels > 4 || array.shape(0) < 1 ||
      array.shape(1) < 1) {
    std::string shape;
    for (py::ssize_t i = 0; i < ndim; ++i) shape += (i ? "×" : "") + std::to_string(array.shape(i));
    throw bad_image(what, fmt::format("{} array of {}", shape.empty() ? "0-d" : shape,
                                      std::string(py::str(dtype.attr("name")))));
  }
  const int rows = static_cast<int>(array.shape(0)), cols = static_cast<int>(array.shape(1));
  cv::Mat mat(rows, cols, CV_MAKETYPE(depth, channels), array.mutable_data());
  return {std::move(array), mat};
}

py::array to_array(cv::Mat mat) {
  if (!mat.isContinuous()) mat = mat.clone();
  py::dtype dtype;
  switch (mat.depth()) {
    case CV_8U:
      dtype = py::dtype::of<std::uint8_t>();
      break;
    case CV_16U:
      dtype = py::dtype::of<std::uint16_t>();
      break;
    case CV_32F:
      dtype = py::dtype::of<float>();
      break;
    case CV_32S:
      dtype = py::dtype::of<std::int32_t>();
      break;
    case CV_64F:
      dtype = py::dtype::of<double>();
      break;
    default:
      throw Error(ErrorKind::unsupported,
                  fmt::format("image: no NumPy dtype for OpenCV depth {}", mat.depth()));
  }
  std::vector<py::ssize_t> shape{mat.rows, mat.cols};
  if (mat.channels() > 1) shape.push_back(mat.channels());
  // The array owns a copy of the Mat header, which shares (and counts a reference to) its pixels.
  auto* keep = new cv::Mat(mat);
  py::capsule owner(keep, [](void* p) { delete static_cast<cv::Mat*>(p); });
  return py::array(dtype, shape, {}, keep->data, owner);
}

cv::Mat swap_red_blue(const cv::Mat& image, bool rgb) {
  if (!rgb || (image.channels() != 3 && image.channels() != 4)) return image;
  cv::Mat out;
  cv::cvtColor(image, out, image.channels() == 3 ? cv::COLOR_BGR2RGB : cv::COLOR_BGRA2RGBA);
  return out;
}

int depth_of(const py::object& dtype, int fallback) {
  if (dtype.is_none()) return fallback;
  const py::dtype d = py::dtype::from_args(dtype);
  if (d.equal(py::dtype::of<std::uint8_t>())) return CV_8U;
  if (d.equal(py::dtype::of<std::uint16_t>())) return CV_16U;
  if (d.equal(py::dtype::of<float>())) return CV_32F;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("dtype: must be uint8, uint16 or float32 (got {})",
                          std::string(py::str(d.attr("name")))));
}

cv::Mat to_depth(const cv::Mat& image, int depth) {
  if (image.depth() == depth) return image;
  cv::Mat out;
  image.convertTo(out, CV_MAKETYPE(depth, image.channels()),
                  full_scale(depth) / full_scale(image.depth()));
  return out;
}

}  // namespace ifsfx::python
