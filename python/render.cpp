// SPDX-License-Identifier: Apache-2.0
#include "python/render.h"

#include <optional>
#include <string>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "flame/flame_chaos.h"
#include "flame/flame_file.h"
#include "flame/render.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/options.h"
#include "python/presets.h"
#include "run/picture_options.h"
#include "run/render_modes.h"
#include "run/render_still.h"

namespace ifsfx::python {
namespace {

// A flame measure's background keyword, as the command's --background for a flame: None keeps
// the file's; "transparent" (with alpha only) or a colour as colour_arg reads it replaces it.
void set_flame_background(flame::Flame& f, const py::object& background, bool alpha) {
  if (background.is_none()) return;
  if (py::isinstance<py::str>(background)) {
    f.tone.background = app::flame_background_option(background.cast<std::string>(), "background");
  } else {
    const Rgb c = colour_arg(background);
    f.tone.background = {c.r, c.g, c.b, 1};
  }
  if (f.tone.background.a == 0 && !alpha)
    throw Error(ErrorKind::invalid_argument,
                "background: \"transparent\" needs alpha=True (got alpha=False)");
}

// A flame (flame/render.h) as an array: BGR, or BGRA over its background's alpha; the GIL
// released while it renders.
cv::Mat flame_picture(flame::Flame f, std::optional<cv::Size> size, std::optional<double> quality,
                      std::uint64_t seed, int threads, bool alpha, const py::object& background) {
  set_flame_background(f, background, alpha);
  return run_released([&](const CancelToken& cancel) {
    return flame::render_flame(f, {.size = size,
                                   .quality = quality,
                                   .seed = seed,
                                   .threads = threads,
                                   .cancel = cancel,
                                   .channels = alpha ? 4 : 3});
  });
}

py::array render_flame(const std::string& spec, const py::object& size, const py::object& quality,
                       std::uint64_t seed, int threads, bool alpha, const py::object& background,
                       const py::object& dtype, bool rgb) {
  const cv::Mat image = flame_picture(
      flame::read_flame(spec), size.is_none() ? std::nullopt : std::optional(size_arg(size)),
      quality.is_none() ? std::nullopt : std::optional(quality.cast<double>()), seed, threads,
      alpha, background);
  return to_array(swap_red_blue(to_depth(image, depth_of(dtype, CV_8U)), rgb));
}

// The keywords a flame's measure takes from its file: a view, or a margin, supersampling, gamma or
// brightness other than the defaults, is refused naming the keyword.
void refuse_flame_keywords(const py::object& view, double margin, int supersample, double gamma,
                           double brightness) {
  const RenderOptions d;
  const auto refuse = [](const char* name, const std::string& got) {
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: a flame's measure takes its own from the file (got {})", name, got));
  };
  if (!view.is_none()) refuse("view", py::str(view).cast<std::string>());
  if (margin != d.sampling.margin) refuse("margin", fmt::format("{}", margin));
  if (supersample != d.supersample) refuse("supersample", fmt::format("{}", supersample));
  if (gamma != d.gamma) refuse("gamma", fmt::format("{}", gamma));
  if (brightness != d.brightness) refuse("brightness", fmt::format("{}", brightness));
}

// `size`, `quality` and `exact` are None unless given, as the command tells a flag given from its
// default: a flame is drawn at its own size (and its measure at its own quality), and an exact
// descent asked for by name is refused for a flame, whose xforms have no inverse.
py::array render(const py::object& preset, const std::string& mode_name, const py::object& size,
                 const py::object& view, double margin, const py::object& quality_arg,
                 int supersample, double gamma, double brightness, std::uint64_t seed, int threads,
                 const py::object& exact_arg, bool second_symbol, const py::object& source,
                 const py::object& colouring, const py::object& background, bool alpha,
                 const py::object& dtype, bool allow_expansive, bool rgb) {
  const app::RenderMode mode = app::parse_render_mode(mode_name);
  const engine::Drawing F = drawing_arg(preset, allow_expansive);
  const auto* as_flame = std::get_if<flame::Flame>(&F);
  const app::StillJob defaults{};
  const cv::Size pixels = !size.is_none() ? size_arg(size)
                          : as_flame ? cv::Size{as_flame->camera.width, as_flame->camera.height}
                                     : defaults.size;
  const std::optional<double> quality =
      quality_arg.is_none() ? std::nullopt : std::optional(quality_arg.cast<double>());
  const bool flame_measure = as_flame && mode == app::RenderMode::measure;
  app::check_mode_options(mode,
                          {.source = {"source", !source.is_none()},
                           .colouring = {"colouring", !colouring.is_none()},
                           .second_symbol = {"second_symbol", second_symbol},
                           .background = {"background", !flame_measure && !background.is_none()}},
                          "mode");
  if (flame_measure) {
    // A flame's measure draws as flam3 does, at its own quality unless given; its camera and
    // tone mapping are the file's, so a keyword that would change them is refused (as the
    // command refuses the flags), not ignored.
    refuse_flame_keywords(view, margin, supersample, gamma, brightness);
    const cv::Mat image =
        flame_picture(*as_flame, pixels, quality, seed, threads, alpha, background);
    return to_array(swap_red_blue(to_depth(image, depth_of(dtype, CV_8U)), rgb));
  }
  if (as_flame && !exact_arg.is_none() && exact_arg.cast<bool>())
    flame::check_flame_chaos({}, true);  // the command's refusal and message
  const bool exact = exact_arg.is_none() ? defaults.exact : exact_arg.cast<bool>();
  const Keywords k = keywords(view, margin, quality.value_or(Sampling{}.quality), supersample,
                              gamma, brightness, seed, threads, exact);
  const bool steal = mode == app::RenderMode::steal;
  app::StillJob job{.mode = mode,
                    .size = pixels,
                    .exact = k.exact && !as_flame,  // a flame: the chaos game
                    .second_symbol = second_symbol,
                    .background = colour_arg(background.is_none() ? py::str("black") : background),
                    .alpha = alpha};
  py::object keep;
  if (steal) {
    job.source = source_arg(source, keep, "source", rgb);
    job.colouring = engine::colouring_for(
        colouring.is_none() ? std::string() : colouring.cast<std::string>(), F, "colouring");
  }
  const cv::Mat image = run_released([&](const CancelToken& cancel) {
    job.options = render_options(k, cancel);
    return app::render_still(F, job).image;
  });
  return to_array(swap_red_blue(to_depth(image, depth_of(dtype, CV_8U)), rgb));
}

}  // namespace

cv::Mat source_arg(const py::handle& source, py::object& keep, const std::string& what, bool rgb) {
  if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
    const std::string path = py::isinstance<py::str>(source)
                                 ? source.cast<std::string>()
                                 : py::str(source.attr("__fspath__")()).cast<std::string>();
    return run_released([&](const CancelToken&) { return read_image(path).pixels; });
  }
  MatView view = to_mat(source, what);
  keep = view.owner;
  return swap_red_blue(view.mat, rgb);
}

namespace {

// read_image and write_image: files as arrays, through the library's image I/O.
void bind_image_files(py::module_& m) {
  m.def(
      "read_image",
      [](const std::string& path, bool rgb) {
        return to_array(swap_red_blue(
            run_released([&](const CancelToken&) { return read_image(path).pixels; }), rgb));
      },
      py::arg("path"), py::kw_only(), py::arg("rgb") = false,
      R"doc(Any image OpenImageIO reads, as stored (uint8, uint16 or float32; BGR, BGRA or grey), alpha
straight; rgb=True gives RGB(A) order. Raises FileNotFoundError or OSError naming the path.)doc");
  m.def(
      "write_image",
      [](const std::string& path, const py::object& image, int bits, bool rgb) {
        const MatView view = to_mat(image, "image");
        const cv::Mat pixels = swap_red_blue(view.mat, rgb);
        run_released([&](const CancelToken& cancel) {
          write_image(path, pixels, {.bits = bits, .output = {.cancel = cancel}});
          return 0;
        });
      },
      py::arg("path"), py::arg("image"), py::arg("bits") = 8, py::kw_only(), py::arg("rgb") = false,
      R"doc(Writes an H×W×C array (BGR order, RGB with rgb=True) in the format of path's extension (.png, .tif, .exr, .jpg),
`bits` 8 (default) or 16 per channel for PNG and TIFF, through a temporary file renamed into
place when complete.)doc");
}

}  // namespace

void bind_render(py::module_& m) {
  const RenderOptions defaults;
  const Sampling sampled;
  const app::StillJob job{};  // the still's defaults, as the command's
  m.def(
      "render", &render, py::arg("preset"), py::kw_only(),
      py::arg("mode") = app::to_string(job.mode), py::arg("size") = py::none(),
      py::arg("view") = py::none(), py::arg("margin") = sampled.margin,
      py::arg("quality") = py::none(), py::arg("supersample") = defaults.supersample,
      py::arg("gamma") = defaults.gamma, py::arg("brightness") = defaults.brightness,
      py::arg("seed") = sampled.seed, py::arg("threads") = sampled.threads,
      py::arg("exact") = py::none(), py::arg("second_symbol") = job.second_symbol,
      py::arg("source") = py::none(), py::arg("colouring") = py::none(),
      py::arg("background") = py::none(), py::arg("alpha") = job.alpha, py::arg("dtype") = "uint8",
      py::arg("allow_expansive") = false, py::arg("rgb") = false,
      R"doc(An IFS rendered as `ifsfx render PRESET -o OUT.png` renders it, as an array equal to the PNG's
pixels (BGR order, like cv2). The GIL is released while it works; Ctrl-C stops it
(KeyboardInterrupt).

preset: a shipped name, a .toml/.ifs path, "FILE.ifs:NAME", an Ifs, or a flame ("art.flame",
    "art.flame:NAME" or an ifsfx.Flame): its measure as flam3 draws it, with the file's
    camera and tone mapping (view, margin, supersample, gamma or brightness other than the
    defaults are refused), the other modes through the chaos game (exact=True is refused: a
    flame's xforms have no inverse).
mode: "attractor" (the set: H×W, 255 on it), "measure" (log-density of the invariant
    measure, coloured by map: H×W×3), "tops" (each pixel coloured by the first symbol of its
    top address: H×W×4, or ×3 with alpha=False), "steal" (colours stolen from `source`:
    its channels, plus alpha).
size: (width, height) or "WxH", default None: (1024, 1024), or a flame's own size.
view: plane rectangle (x0, y0, x1, y1) shown, default None: the attractor, auto-framed
    with `margin` (default 0.05, fraction of the larger side).
quality: chaos-game points per output pixel, default None: 64, or a flame measure's own
    quality (flam3's samples per pixel).
supersample: measure mode: render at K times the size and box-filter down, default 1.
gamma, brightness: measure mode's tone map, defaults 2.2 and 4.
seed: default 1; the same seed gives the same array for any thread count.
threads: default 0 = all cores.
exact: tops and steal: the exact per-pixel descent (default None: True for an IFS, the chaos
    game for a flame) or the chaos game (False).
second_symbol: tops mode: mix in the second symbol's colour, default False.
source: steal mode: the image (an H×W×C uint8/uint16/float32 array, or a path).
colouring: steal mode: colouring IFS preset with as many maps, default None: a tiling.
background: tops and steal: colour off the attractor ("black", "white", "#rrggbb" or
    (R, G, B)), default None: black; alpha is 0 there. A flame's measure: None keeps the
    file's, a colour or "transparent" (with alpha=True) replaces it, as render_flame.
alpha: tops, steal and a flame's measure: keep the coverage as an alpha channel (as PNG),
    default True.
dtype: "uint8" (default, as an 8-bit PNG), "uint16" (as a 16-bit PNG) or "float32" (in [0, 1]).
rgb: False (default): arrays in and out in BGR(A) order, like cv2; True: RGB(A).
allow_expansive: accept maps of factor >= 1 when the IFS contracts on average, default False.

Raises ValueError for bad input (with the library's message), FileNotFoundError/OSError for
files.)doc");

  m.def("render_flame", &render_flame, py::arg("spec"), py::kw_only(), py::arg("size") = py::none(),
        py::arg("quality") = py::none(), py::arg("seed") = 1, py::arg("threads") = 0,
        py::arg("alpha") = false, py::arg("background") = py::none(), py::arg("dtype") = "uint8",
        py::arg("rgb") = false,
        R"doc(A fractal flame of flam3, Apophysis, JWildfire or Fractorium ("art.flame",
"art.flame:NAME" or "art.flame:INDEX") as `ifsfx render art.flame:NAME -o OUT.png` renders it,
as flam3-render does: H×W×3 (BGR over the flame's background), or ×4 with alpha=True (opaque
unless the file's background is transparent: then the flame's cover).
size: (width, height) or "WxH", default None: the flame's own (the framing kept).
quality: samples per pixel, default None: the flame's own.
seed: default 1; the same seed gives the same array for any thread count. threads: 0 = all.
background: default None: the flame's own; a colour ("black", "white", "#rrggbb", "R,G,B") in
    its place, or "transparent" (with alpha=True: the cover as alpha, as flam3-render's
    transparency=1), as the command's --background.
dtype: "uint8" (default), "uint16" or "float32". rgb: True for RGB order.
ifsfx.render(spec, mode="measure", ...) draws the same at its size and quality.)doc");
  bind_image_files(m);
}

}  // namespace ifsfx::python
