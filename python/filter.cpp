// SPDX-License-Identifier: Apache-2.0
#include "python/filter.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <opencv2/core.hpp>

#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/options.h"
#include "python/presets.h"
#include "run/filter_options.h"

namespace ifsfx::python {
namespace {

// One engine and the frame counter. The engine is made (the preset loaded and checked) at once;
// its maps are prepared for the first frame's size, or for frame_size= ahead. A stop (Ctrl-C)
// while maps are built leaves the engine unusable (a keyframe that was stopped stays stopped), so
// the next call starts a fresh one: frames are pure functions of the settings, size and index.
class Filter {
 private:
  // The work on a thread of its own, the GIL released, stopped by Ctrl-C; one call at a time.
  template <class Work>
  decltype(auto) released(Work&& work) {
    try {
      return run_released(
          [&](const CancelToken&) {
            const std::lock_guard lock(mutex_);
            return work();
          },
          *stop_);
    } catch (...) {
      if (stop_->load()) restart();
      throw;
    }
  }

 public:
  Filter(engine::FractalSettings settings, std::optional<cv::Size> output_size,
         std::optional<cv::Size> frame_size, double fps, bool rgb)
      : settings_(std::move(settings)), output_size_(output_size), fps_(fps), rgb_(rgb) {
    settings_.sampling.cancel = CancelToken(stop_.get());
    engine_ = std::make_unique<engine::FractalEngine>(settings_);
    if (!(fps > 0 && fps <= 1000))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("fps: must be in (0, 1000] (got {})", fps));
    if (frame_size)
      released([&] {
        prepare(*frame_size);
        return 0;
      });
  }

  ~Filter() {
    *stop_ = true;  // keyframes being built ahead end at once
    const py::gil_scoped_release release;
    engine_.reset();
  }

  Filter(const Filter&) = delete;
  Filter& operator=(const Filter&) = delete;

  py::array apply(const py::object& frame, std::optional<std::int64_t> index) {
    const MatView view = to_mat(frame, "frame");
    if (view.mat.depth() != CV_8U || (view.mat.channels() != 3 && view.mat.channels() != 4))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("frame: a frame is an H×W×3 (BGR) or H×W×4 (BGRA) array of uint8 "
                              "(got {}×{}×{} array of {})",
                              view.mat.rows, view.mat.cols, view.mat.channels(),
                              std::string(py::str(view.owner.dtype().attr("name")))));
    const cv::Mat bgr = swap_red_blue(view.mat, rgb_);
    const std::int64_t k = index.value_or(next_);
    cv::Mat out = released([&]() -> cv::Mat {
      if (!frame_size_) prepare(bgr.size());
      return engine_->filter(bgr, k);
    });
    next_ = k + 1;
    return to_array(swap_red_blue(out, rgb_));
  }

  std::int64_t next_index() const { return next_; }
  void set_next_index(std::int64_t index) { next_ = index; }
  const std::string& name() const { return engine_->name(); }
  py::object frame_size() const {
    if (!frame_size_) return py::none();
    return py::make_tuple(frame_size_->width, frame_size_->height);
  }
  py::object output_size() const {
    if (!frame_size_) return py::none();
    const cv::Size s = output_size_.value_or(*frame_size_);
    return py::make_tuple(s.width, s.height);
  }
  std::int64_t stalls() const { return engine_->stalls(); }

 private:
  void prepare(cv::Size frame_size) {
    engine_->prepare(frame_size, output_size_.value_or(cv::Size()), fps_);
    frame_size_ = frame_size;
  }

  // A fresh engine after a stop (the old one's stopped keyframes end first).
  void restart() {
    {
      const py::gil_scoped_release release;
      const std::lock_guard lock(mutex_);
      engine_ = std::make_unique<engine::FractalEngine>(settings_);
      frame_size_.reset();
    }
    *stop_ = false;
  }

  engine::FractalSettings settings_;
  std::optional<cv::Size> output_size_, frame_size_;
  double fps_;
  bool rgb_;
  std::int64_t next_ = 0;
  std::unique_ptr<std::atomic<bool>> stop_ = std::make_unique<std::atomic<bool>>(false);
  std::mutex mutex_;
  std::unique_ptr<engine::FractalEngine> engine_;
};

std::optional<cv::Size> optional_size(const py::object& size, const std::string& what) {
  if (size.is_none()) return std::nullopt;
  return size_arg(size, what);
}

constexpr const char* kFilterDoc = R"doc(
The video filter of `ifsfx filter`, frame by frame: each frame coloured through the fractal's
steal map, for frames that come from cv2.VideoCapture, PyAV or a camera. A frame is a pure
function of the settings, its size and its index, equal to the frame `ifsfx filter` writes:

    f = ifsfx.Filter("barnsley-fern", animate="drift")
    while (frame := capture.read()[1]) is not None:
        out = f(frame)        # frame 0, 1, 2, ...

The maps are prepared on the first frame's size (or on frame_size= at once); every later frame
must have that size (ValueError otherwise).
)doc";

// The keywords' docstring, its defaults the engine's (d) and the command's (fps).
std::string filter_init_doc(const engine::FractalSettings& d, double fps) {
  return fmt::format(
      R"doc(The settings of `ifsfx filter`, keyword for flag, with its defaults:

preset: the drawing IFS F: a shipped name, a .toml/.ifs path, "FILE.ifs:NAME", or a flame
    ("art.flame:NAME" or an ifsfx.Flame: through the chaos game), default "{}".
colouring: the colouring IFS G (as many maps as F), default None: a tiling of the frame.
view: plane rectangle (x0, y0, x1, y1) or "x0,y0,x1,y1" shown on the frame, default None:
    the attractor, auto-framed with `margin` (default {}).
quality: exact=False: chaos-game points per pixel, default {}.
mix: weight of the original frame blended over the fractal, 0..1, default {}.
background: where the attractor does not reach: "black" (default), "white", "original",
    "#rrggbb", "R,G,B" or (R, G, B).
exact: the exact per-pixel descent (default None: True for an IFS; a flame always takes the
    chaos game, and refuses exact=True) or the chaos game (False).
seed: default {}. threads: default 0 = all cores; the frames never depend on it.
interpolation: "bilinear" (default) or "nearest".
animate: "none" (default, or None: one fixed map), "drift" (the maps wander by fBm noise) or
    "superifs" (a V-variable step of `superifs` per keyframe).
drift_amount: default {}. drift_speed: cycles per second, default {}.
keyframe_interval: frames between rebuilt maps, cross-faded between, default {}.
superifs: default "{}". buffers: its V, default {}.
loop: the animation repeats every `loop` frames, bit for bit, default 0: never.
size: output (width, height) or "WxH", default None: the frame's (as --size).
frame_size: prepare the maps now for frames of this size, default None: on the first frame.
fps: frames per second, turning frame numbers into the animation's time, default {} (as the
    command's --fps for an image sequence; give a movie's own rate).
rgb: frames in and out in RGB(A) order, default False (BGR(A), like cv2).

Raises ValueError for bad settings (with the command's messages), FileNotFoundError for a
missing preset file. Preparing the maps releases the GIL and stops on Ctrl-C.)doc",
      engine::kDefaultPreset, d.sampling.margin, d.sampling.quality, d.mix, d.sampling.seed,
      d.drift_amount, d.drift_speed, d.keyframe_interval, d.superifs, d.buffers, fps);
}

// ifsfx.Filter(...): the keywords as the engine's settings, then the engine made.
std::unique_ptr<Filter> make_filter(const py::object& preset, const py::object& colouring,
                                    const py::object& view, double margin, double quality,
                                    double mix, const py::object& background,
                                    const py::object& exact, std::uint64_t seed, int threads,
                                    const std::string& interpolation, const py::object& animate,
                                    double drift_amount, double drift_speed, int keyframe_interval,
                                    const py::object& superifs, int buffers, std::int64_t loop,
                                    const py::object& size, const py::object& frame_size,
                                    double fps, bool rgb) {
  const engine::FractalSettings settings =
      fractal_settings({.preset = preset,
                        .colouring = colouring,
                        .view = view,
                        .background = background,
                        .animate = animate,
                        .interpolation = interpolation,
                        .margin = margin,
                        .quality = quality,
                        .mix = mix,
                        .drift_amount = drift_amount,
                        .drift_speed = drift_speed,
                        .exact = exact,
                        .seed = seed,
                        .threads = threads,
                        .keyframe_interval = keyframe_interval,
                        .buffers = buffers,
                        .superifs = spec_arg(superifs, "superifs"),
                        .loop = loop});
  return std::make_unique<Filter>(settings, optional_size(size, "size"),
                                  optional_size(frame_size, "frame_size"), fps, rgb);
}

}  // namespace

void bind_filter(py::module_& m) {
  const engine::FractalSettings d;
  const app::FilterArgs filter_defaults;  // a named object: GCC 12 warns on the temporary's string
  const double fps = filter_defaults.fps;
  py::class_<Filter>(m, "Filter", kFilterDoc)
      .def(py::init(&make_filter), py::arg("preset") = engine::kDefaultPreset, py::kw_only(),
           py::arg("colouring") = py::none(), py::arg("view") = py::none(),
           py::arg("margin") = d.sampling.margin, py::arg("quality") = d.sampling.quality,
           py::arg("mix") = d.mix, py::arg("background") = "black", py::arg("exact") = py::none(),
           py::arg("seed") = d.sampling.seed, py::arg("threads") = d.sampling.threads,
           py::arg("interpolation") = "bilinear", py::arg("animate") = "none",
           py::arg("drift_amount") = d.drift_amount, py::arg("drift_speed") = d.drift_speed,
           py::arg("keyframe_interval") = d.keyframe_interval, py::arg("superifs") = d.superifs,
           py::arg("buffers") = d.buffers, py::arg("loop") = d.loop, py::arg("size") = py::none(),
           py::arg("frame_size") = py::none(), py::arg("fps") = fps, py::arg("rgb") = false,
           filter_init_doc(d, fps).c_str())
      .def("__call__", &Filter::apply, py::arg("frame"), py::arg("index") = py::none(),
           "f(frame, index=None): see apply().")
      .def("apply", &Filter::apply, py::arg("frame"), py::arg("index") = py::none(),
           R"doc(Frame `index` filtered (default None: the frame after the last one, from 0): an
H×W×3 (BGR) or H×W×4 (BGRA, its alpha passed through) uint8 array in, an array of the output
size and the frame's channels out. The first frame prepares the maps for its size; a frame of
another size raises ValueError. The GIL is released; Ctrl-C stops a map being built.)doc")
      .def_property("index", &Filter::next_index, &Filter::set_next_index,
                    "the index the next frame gets when none is given (starts at 0)")
      .def_property_readonly("name", &Filter::name,
                             "F's name, or the superIFS's with animate=\"superifs\"")
      .def_property_readonly("frame_size", &Filter::frame_size,
                             "(width, height) of the frames the maps are prepared for, or None")
      .def_property_readonly("size", &Filter::output_size,
                             "(width, height) of the output frames, or None before the first")
      .def_property_readonly(
          "stalls", &Filter::stalls,
          "frames that waited for a keyframe being built (animations; 0 for a fixed map)")
      .def("__repr__",
           [](const Filter& f) { return fmt::format("<ifsfx.Filter '{}'>", f.name()); });
}

}  // namespace ifsfx::python
