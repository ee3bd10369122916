// SPDX-License-Identifier: Apache-2.0
#include "python/errors.h"

#include "ifs/error.h"

namespace ifsfx::python {

void register_errors(py::module_& m) {
  (void)m;
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Error& e) {
      PyObject* type = PyExc_ValueError;
      switch (e.kind()) {
        case ErrorKind::parse:
        case ErrorKind::invalid_ifs:
        case ErrorKind::invalid_argument:
        case ErrorKind::unsupported:
          type = PyExc_ValueError;
          break;
        case ErrorKind::not_found:
          type = PyExc_FileNotFoundError;
          break;
        case ErrorKind::io:
        case ErrorKind::device:
          type = PyExc_OSError;
          break;
        case ErrorKind::interrupted:
          type = PyExc_KeyboardInterrupt;
          break;
      }
      PyErr_SetString(type, e.what());
    }
  });
}

}  // namespace ifsfx::python
