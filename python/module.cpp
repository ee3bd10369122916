// SPDX-License-Identifier: Apache-2.0
// The Python module `ifsfx` (docs/python.md): the engine of the ifsfx command on NumPy arrays.
#include <pybind11/pybind11.h>

#include "python/errors.h"
#include "python/filter.h"
#include "python/fit.h"
#include "python/fractaldb.h"
#include "python/presets.h"
#include "python/render.h"
#include "python/steal.h"
#include "python/texture.h"

PYBIND11_MODULE(ifsfx, m) {
  m.doc() = R"doc(ifsfx: images and video into fractals, on NumPy arrays.

IFS rendering by the chaos game (attractor, invariant measure), fractal tops, colour stealing
through steal maps, and V-variable superfractal textures: the engine of the `ifsfx` command,
with the same results byte for byte. Images are H×W or H×W×C arrays of uint8, uint16 or
float32 in BGR order, like cv2. Long computations release the GIL and stop on Ctrl-C.

    import ifsfx
    a = ifsfx.render("barnsley-fern", mode="measure", size=(512, 512))
)doc";
#ifdef IFSFX_VERSION
  m.attr("__version__") = IFSFX_VERSION;
#endif
  ifsfx::python::register_errors(m);
  ifsfx::python::bind_presets(m);
  ifsfx::python::bind_render(m);
  ifsfx::python::bind_steal(m);
  ifsfx::python::bind_texture(m);
  ifsfx::python::bind_fractaldb(m);
  ifsfx::python::bind_fit(m);
  ifsfx::python::bind_filter(m);
}
