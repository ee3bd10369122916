// SPDX-License-Identifier: Apache-2.0
#include "python/options.h"

#include "python/presets.h"

#include <cctype>
#include <string>

#include <fmt/format.h>

#include "ifs/error.h"
#include "run/filter_options.h"
#include "run/fractal_filter_options.h"
#include "run/picture_options.h"

namespace ifsfx::python {

Keywords keywords(const py::object& view, double margin, double quality, int supersample,
                  double gamma, double brightness, std::uint64_t seed, int threads, bool exact) {
  return {.render = {.sampling = {.view = view_arg(view),
                                  .margin = margin,
                                  .quality = quality,
                                  .seed = seed,
                                  .threads = threads},
                     .supersample = supersample,
                     .gamma = gamma,
                     .brightness = brightness},
          .exact = exact};
}

RenderOptions render_options(const Keywords& k, const CancelToken& cancel) {
  RenderOptions o = k.render;
  o.sampling.cancel = cancel;
  return o;
}

TopsOptions tops_options(const Keywords& k, const CancelToken& cancel) {
  return {.sampling = render_options(k, cancel).sampling, .exact = k.exact};
}

StealMapOptions steal_map_options(const Keywords& k, const CancelToken& cancel) {
  return {.sampling = render_options(k, cancel).sampling, .exact = k.exact};
}

Interpolation interpolation_arg(const std::string& name) {
  if (name == "bilinear") return Interpolation::bilinear;
  if (name == "nearest") return Interpolation::nearest;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("interpolation: bilinear or nearest (got '{}')", name));
}

std::string spec_arg(const py::object& spec, const std::string& what) {
  if (spec.is_none()) return {};
  if (py::isinstance<py::str>(spec)) return spec.cast<std::string>();
  if (py::hasattr(spec, "__fspath__"))
    return py::str(spec.attr("__fspath__")()).cast<std::string>();
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: a name or a path (got {})", what,
                          std::string(py::str(py::type::of(spec).attr("__name__")))));
}

engine::Background filter_background_arg(const py::object& background) {
  if (py::isinstance<py::str>(background))
    return engine::parse_background(background.cast<std::string>(), "background");
  // (R, G, B): through the parser, so that a bad one gets its message.
  if (py::isinstance<py::sequence>(background) && py::len(background) == 3) {
    const py::sequence rgb = background.cast<py::sequence>();
    if (py::isinstance<py::int_>(rgb[0]) && py::isinstance<py::int_>(rgb[1]) &&
        py::isinstance<py::int_>(rgb[2]))
      return engine::parse_background(
          fmt::format("{},{},{}", rgb[0].cast<long long>(), rgb[1].cast<long long>(),
                      rgb[2].cast<long long>()),
          "background");
  }
  throw Error(ErrorKind::invalid_argument,
              fmt::format("background: black, white, original, #rrggbb or (R, G, B) (got {})",
                          std::string(py::repr(background))));
}

namespace {

engine::Animate animate_arg(const py::object& animate) {
  const std::string name = animate.is_none() ? "none" : py::str(animate).cast<std::string>();
  if (!animate.is_none() && !py::isinstance<py::str>(animate))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("animate: none, drift or superifs (got {})", std::string(py::repr(animate))));
  if (name == "none") return engine::Animate::none;
  if (name == "drift") return engine::Animate::drift;
  if (name == "superifs") return engine::Animate::superifs;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("animate: none, drift or superifs (got '{}')", name));
}

}  // namespace

engine::FractalSettings fractal_settings(const FilterKeywords& k) {
  const bool named_exact = !k.exact.is_none();
  engine::FractalSettings s{
      .exact = named_exact ? k.exact.cast<bool>() : engine::FractalSettings{}.exact,
      .sampling = {.view = view_arg(k.view),
                   .margin = k.margin,
                   .quality = k.quality,
                   .seed = k.seed,
                   .threads = k.threads},
      .mix = k.mix,
      .background = filter_background_arg(k.background),
      .interpolation = interpolation_arg(k.interpolation),
      .animate = animate_arg(k.animate),
      .drift_amount = k.drift_amount,
      .drift_speed = k.drift_speed,
      .keyframe_interval = k.keyframe_interval,
      .superifs = k.superifs,
      .buffers = k.buffers,
      .loop = k.loop};
  // The command's rule (check_filter_rules), in the keywords' words.
  app::check_loop_rule(
      s.loop, s.animate,
      {.loop = "loop", .drift = "animate=\"drift\"", .superifs = "animate=\"superifs\""});
  // F and G as data, the preset read as render() reads it (an unknown name is a ValueError, a
  // Fractint entry that contracts only on average a UserWarning); a superIFS brings its own.
  if (s.animate != engine::Animate::superifs) {
    engine::Drawing F = drawing_arg(k.preset);
    app::refuse_named_exact(F, s.exact, named_exact, "exact");  // as `ifsfx filter --exact`
    const std::string colouring = spec_arg(k.colouring, "colouring");
    if (!colouring.empty()) s.colouring = engine::colouring_for(colouring, F, "colouring");
    s.drawing = std::move(F);
  }
  return s;
}

cv::Size size_arg(const py::object& size, const std::string& what) {
  if (py::isinstance<py::str>(size)) return parse_size(size.cast<std::string>(), what);
  if (py::isinstance<py::sequence>(size) && py::len(size) == 2) {
    const py::sequence wh = size.cast<py::sequence>();
    if (py::isinstance<py::int_>(wh[0]) && py::isinstance<py::int_>(wh[1]))
      return parse_size(fmt::format("{}x{}", wh[0].cast<long long>(), wh[1].cast<long long>()),
                        what);
  }
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: a size is (width, height) or \"WxH\" (got {})", what,
                          std::string(py::repr(size))));
}

std::optional<Box> view_arg(const py::object& view, const std::string& what) {
  if (view.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(view)) return parse_box(view.cast<std::string>(), what);
  if (py::isinstance<py::sequence>(view) && py::len(view) == 4) {
    const py::sequence v = view.cast<py::sequence>();
    // Through parse_box, so that a bad rectangle gets the CLI's message.
    return parse_box(fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}", v[0].cast<double>(),
                                 v[1].cast<double>(), v[2].cast<double>(), v[3].cast<double>()),
                     what);
  }
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: a view is (x0, y0, x1, y1) or \"x0,y0,x1,y1\" (got {})", what,
                          std::string(py::repr(view))));
}

Rgb colour_arg(const py::object& colour, const std::string& what) {
  // Through the command's parser (run/picture_options.h), so that a bad one gets its message.
  if (py::isinstance<py::str>(colour)) return app::colour_option(colour.cast<std::string>(), what);
  if (py::isinstance<py::sequence>(colour) && py::len(colour) == 3) {
    const py::sequence rgb = colour.cast<py::sequence>();
    if (py::isinstance<py::int_>(rgb[0]) && py::isinstance<py::int_>(rgb[1]) &&
        py::isinstance<py::int_>(rgb[2]))
      return app::colour_option(fmt::format("{},{},{}", rgb[0].cast<long long>(),
                                            rgb[1].cast<long long>(), rgb[2].cast<long long>()),
                                what);
  }
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: a colour is black, white, #rrggbb or (R, G, B) with 0..255 (got {})",
                          what, std::string(py::repr(colour))));
}

}  // namespace ifsfx::python
