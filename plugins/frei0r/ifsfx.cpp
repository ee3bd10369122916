// SPDX-License-Identifier: Apache-2.0
// The `ifsfx` frei0r filter: the fractal filter of `ifsfx filter` (paper §6) inside FFmpeg, MLT
// (melt, Kdenlive, Shotcut) and GStreamer. A thin adapter: the parameters become one
// engine::FractalSettings and every frame goes through one engine::FractalEngine, the object
// `ifsfx filter` itself uses — no mathematics here.
//
// A bad parameter (unknown preset, unreadable file, bad colour or view) never stops the host: it is
// reported once on stderr, and frames pass through unchanged until it is fixed. Unchanged rather
// than black: in an editor the clip stays visible while a preset name is being typed, and a render
// that was started with a typo still holds the footage; the stderr line says why it is unfiltered.
#include <cmath>
#include <cstring>
#include <future>
#include <memory>
#include <mutex>
#include <optional>

#include <fmt/format.h>
#include <opencv2/core.hpp>

#include "engine/fractal_engine.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/view.h"
#include "plugins/frei0r/host.h"
#include "plugins/frei0r/host_clock.h"
#include "plugins/frei0r/params.h"
#include "superifs/texture.h"

namespace ifsfx::frei0r {
namespace {

constexpr const char* plugin_name = "ifsfx";

// The parameters, in the order hosts address them by position. Do not reorder or rename.
enum Param { preset, colouring, mix, background, exact, drift, speed, seed, view, rate, loop };
constexpr ParamInfo table[] = {
    {"preset", ParamType::text,
     "The drawing F: a shipped name (see `ifsfx presets`), a .toml/.ifs path, FILE.ifs:NAME, or "
     "a flame, FILE.flame[:NAME]",
     0, engine::kDefaultPreset},
    {"colouring", ParamType::text,
     "The colouring IFS G on the frame, with as many maps as F (empty: a tiling of the frame)"},
    {"mix", ParamType::number, "Weight of the original frame blended over the fractal, 0..1", 0},
    {"background", ParamType::text,
     "Where the attractor does not cover: black, white, original, #rrggbb or R,G,B", 0, "black"},
    {"exact", ParamType::flag,
     "Tops by the exact per-pixel descent (default: faster, no noise); off: the chaos game", 1},
    {"drift", ParamType::number,
     "Animation: how far the map coefficients wander by fBm noise, 0..1 (0: one fixed map)", 0},
    {"speed", ParamType::number, "Animation: cycles per second of the slowest drift",
     engine::kDefaultDriftSpeed},
    {"seed", ParamType::number, "Random seed, a whole number: the same seed gives the same frames",
     1},
    {"view", ParamType::text,
     "Plane rectangle x0,y0,x1,y1 shown on the frame (empty: the attractor, auto-framed)"},
    {"rate", ParamType::number,
     "Animation: frames per second to count by when the host gives no frame times (FFmpeg 5.1 "
     "at widths that are not a multiple of 64)",
     default_count_rate},
    {"loop", ParamType::number,
     "Animation: seconds after which the drift repeats, frame for frame, rounded to whole frames "
     "of 25 fps (0: never)",
     0},
};

// The presets of the parameters, loaded: hosts pass every parameter again with every frame, and
// a preset is read again only when its text changes (one that failed is not tried again either).
class LoadedPresets {
 public:
  void load(const std::string& preset, const std::string& colouring) {
    if (preset == preset_ && colouring == colouring_) {
      if (!error_.empty()) throw Error(ErrorKind::invalid_argument, error_);
      if (loaded_) return;
    }
    preset_ = preset;
    colouring_ = colouring;
    error_.clear();
    loaded_ = false;
    try {
      engine::Drawing F = engine::load_drawing(preset);
      G_.reset();
      if (!colouring.empty()) G_ = engine::colouring_for(colouring, F, "colouring");
      F_ = std::move(F);
      loaded_ = true;
    } catch (const Error& e) {
      error_ = e.what();
      throw;
    }
  }
  const engine::Drawing& drawing() const { return F_; }
  const std::optional<Ifs>& colouring() const { return G_; }

 private:
  bool loaded_ = false;
  std::string preset_, colouring_, error_;
  engine::Drawing F_;
  std::optional<Ifs> G_;
};

// The engine's settings for parameter values; throws ifsfx::Error naming the parameter.
engine::FractalSettings settings_of(const ParamValues::Values& v, LoadedPresets& presets) {
  engine::FractalSettings s;
  presets.load(v.text(preset).empty() ? table[preset].text : v.text(preset), v.text(colouring));
  s.drawing = presets.drawing();
  s.colouring = presets.colouring();
  s.mix = v.number(mix);
  s.background = engine::parse_background(v.text(background), "background");
  // Frames are RGBA: the colour's channels in that order.
  const cv::Scalar bgr = s.background.colour;
  s.background.colour = cv::Scalar(bgr[2], bgr[1], bgr[0], 255);
  s.exact = v.flag(exact);
  const double amount = v.number(drift);
  if (!(amount >= 0 && amount <= 1))
    throw Error(ErrorKind::invalid_argument,
                "drift: must be in [0, 1] (got " + std::to_string(amount) + ")");
  s.animate = amount > 0 ? engine::Animate::drift : engine::Animate::none;
  s.drift_amount = amount;
  s.drift_speed = v.number(speed);
  s.sampling.seed = static_cast<std::uint64_t>(whole_number(v.number(seed), "seed", 0, 1LL << 53));
  if (!v.text(view).empty()) s.sampling.view = parse_box(v.text(view), "view");
  // The engine counts a loop in frames of its nominal rate, as it places the drift's keyframes.
  const double loop_seconds = v.number(loop);
  if (!(loop_seconds >= 0 && loop_seconds <= kMaxLoop / nominal_frame_rate))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("loop: must be 0..{:g} seconds (got {})", kMaxLoop / nominal_frame_rate,
                            loop_seconds));
  s.loop = std::llround(loop_seconds * nominal_frame_rate);
  frame_rate_parameter(v.number(rate));
  return s;
}

class FilterInstance {
 public:
  FilterInstance(unsigned width, unsigned height)
      : size_(static_cast<int>(width), static_cast<int>(height)) {}
  ~FilterInstance() {
    if (prefetch_.valid()) prefetch_.wait();
  }

  ParamValues& params() { return values_; }

  // A parameter changed while frames are flowing: start building the new maps now, so that the
  // next frame finds them ready (a GStreamer property set from the application's thread). Before
  // the first frame nothing is built: hosts set every parameter first, one by one.
  void changed() {
    std::lock_guard lock(mutex_);
    if (!engine_ || prefetch_.valid()) return;
    std::optional<engine::FractalSettings> s;
    try {
      s = settings_of(values_.values(), presets_);
    } catch (const Error&) {
      return;  // reported by the next frame
    }
    if (same_maps(engine_->settings(), *s)) return;
    prefetch_settings_ = *s;
    prefetch_ = std::async(std::launch::async, [s = *s, size = size_] {
      return std::make_unique<engine::FractalEngine>(s, size, size, nominal_frame_rate);
    });
  }

  // One frame at the host's `host_time`, in `unit` (host_clock.h: checked before it is trusted).
  void update(double host_time, TimeUnit unit, const std::uint32_t* in, std::uint32_t* out) {
    const std::size_t bytes = static_cast<std::size_t>(size_.area()) * 4;
    if (in == nullptr || out == nullptr) return;
    std::lock_guard lock(mutex_);
    if (!clock_) clock_.emplace(unit);
    const ParamValues::Values v = values_.values();
    // Every frame is counted, filtered or not: the count is the clock of a host without times.
    const HostClock::Reading at = clock_->next(host_time, v.number(rate));
    try {
      const engine::FractalSettings s = settings_of(v, presets_);
      if (at.counted && s.animate != engine::Animate::none)
        clock_reporter_.report(fmt::format(
            "the host gives no frame times; animating by frame count at {:g} fps", at.rate));
      engine_for(s);
      const cv::Mat frame(size_, CV_8UC4, const_cast<std::uint32_t*>(in));
      cv::Mat result(size_, CV_8UC4, out);
      engine_->filter_at(frame, at.seconds, result);
      if (result.data != reinterpret_cast<std::uint8_t*>(out))  // never: same size and type
        result.copyTo(cv::Mat(size_, CV_8UC4, out));
      reporter_.clear();
    } catch (const std::exception& e) {
      reporter_.report(std::string(e.what()) + "; frames pass through unchanged");
      if (in != out) std::memcpy(out, in, bytes);
    } catch (...) {
      reporter_.report("unexpected failure; frames pass through unchanged");
      if (in != out) std::memcpy(out, in, bytes);
    }
  }

 private:
  // An engine for `s`: the one in use (a new mix or background needs no new maps), the prefetched
  // one, or a new one. Settings that failed are not tried again on every frame.
  void engine_for(const engine::FractalSettings& s) {
    if (engine_ && same_maps(engine_->settings(), s)) {
      if (engine_->settings() != s) engine_->set_look(s.mix, s.background);
      return;
    }
    if (failed_ && failed_->first == s) throw Error(ErrorKind::invalid_argument, failed_->second);
    std::unique_ptr<engine::FractalEngine> next;
    if (prefetch_.valid()) {
      try {
        next = prefetch_.get();  // waits: it has been working since the parameter changed
      } catch (const std::exception&) {
        next.reset();  // built again below, where its error is reported
      }
      if (next && !same_maps(prefetch_settings_, s)) next.reset();
    }
    try {
      if (!next)
        next = std::make_unique<engine::FractalEngine>(s, size_, size_, nominal_frame_rate);
      next->set_look(s.mix, s.background);
    } catch (const std::exception& e) {
      failed_.emplace(s, e.what());
      throw;
    }
    failed_.reset();
    engine_ = std::move(next);
  }

  cv::Size size_;
  ParamValues values_{table};
  Reporter reporter_{plugin_name};
  Reporter clock_reporter_{plugin_name};  // once per instance (and per rate), never cleared
  std::optional<HostClock> clock_;        // made by the first frame, which shows who the host is
  std::mutex mutex_;  // a parameter set from another thread while a frame is made (GStreamer)
  LoadedPresets presets_;
  std::unique_ptr<engine::FractalEngine> engine_;
  std::future<std::unique_ptr<engine::FractalEngine>> prefetch_;
  engine::FractalSettings prefetch_settings_;
  std::optional<std::pair<engine::FractalSettings, std::string>> failed_;
};

}  // namespace
}  // namespace ifsfx::frei0r

using ifsfx::frei0r::FilterInstance;

extern "C" {

// No global state: f0r_init and f0r_deinit have nothing to do (GStreamer does not even call
// f0r_init in a process that found the plugin in its registry cache).
IFSFX_F0R_EXPORT int f0r_init() {
  return 1;
}
IFSFX_F0R_EXPORT void f0r_deinit() {}

IFSFX_F0R_EXPORT void f0r_get_plugin_info(f0r_plugin_info_t* info) {
  info->name = ifsfx::frei0r::plugin_name;
  info->author = "ifsfx";
  info->plugin_type = F0R_PLUGIN_TYPE_FILTER;
  info->color_model = F0R_COLOR_MODEL_RGBA8888;
  info->frei0r_version = FREI0R_MAJOR_VERSION;
  info->major_version = 0;
  info->minor_version = 1;
  info->num_params = static_cast<int>(std::size(ifsfx::frei0r::table));
  info->explanation =
      "Fractal filter: every frame coloured through the steal map of an IFS (colour stealing)";
}

IFSFX_F0R_EXPORT void f0r_get_param_info(f0r_param_info_t* info, int index) {
  ifsfx::frei0r::describe(ifsfx::frei0r::table, info, index);
}

IFSFX_F0R_EXPORT f0r_instance_t f0r_construct(unsigned int width, unsigned int height) {
  try {
    return new FilterInstance(width, height);
  } catch (...) {
    return nullptr;  // out of memory: the host reports that it could not make an instance
  }
}

IFSFX_F0R_EXPORT void f0r_destruct(f0r_instance_t instance) {
  delete static_cast<FilterInstance*>(instance);
}

IFSFX_F0R_EXPORT void f0r_set_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
  auto* self = static_cast<FilterInstance*>(instance);
  try {
    if (self->params().set(param, index)) self->changed();
  } catch (...) {
    // Nothing started: the next frame builds what it needs and reports any fault.
  }
}

IFSFX_F0R_EXPORT void f0r_get_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
  static_cast<FilterInstance*>(instance)->params().get(param, index);
}

IFSFX_F0R_EXPORT void f0r_update(f0r_instance_t instance, double time, const uint32_t* inframe,
                                 uint32_t* outframe) {
  static_cast<FilterInstance*>(instance)->update(
      time, ifsfx::frei0r::host_time_unit(__builtin_return_address(0)), inframe, outframe);
}

}  // extern "C"
