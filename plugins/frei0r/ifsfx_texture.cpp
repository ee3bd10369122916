// SPDX-License-Identifier: Apache-2.0
// The `ifsfx-texture` frei0r source: a V-variable superfractal texture sequence (paper §5,
// Fig. 4–5) as a video, the frames of `ifsfx texture --frames` — superifs' TextureSequence does
// the work; this file only maps parameters and time onto it.
//
// The host's time picks the step: step ⌊t · speed⌋, crossfaded towards the next by the fraction
// (or cut, without crossfade). Each step is a pure function of its number (and the settings), so
// scrubbing backwards or starting mid-clip shows the frames a run from the start shows.
//
// A bad parameter is reported once on stderr and the frames are black until it is fixed: a
// source has no picture of its own to pass through.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/timeline.h"
#include "plugins/frei0r/host.h"
#include "plugins/frei0r/host_clock.h"
#include "plugins/frei0r/params.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace ifsfx::frei0r {
namespace {

constexpr const char* plugin_name = "ifsfx-texture";

// The parameters, in the order hosts address them by position. Do not reorder or rename.
enum Param { preset, buffers, mode, source, seed, speed, crossfade, rate, loop };
constexpr ParamInfo table[] = {
    {"preset", ParamType::text,
     "The superIFS: a shipped name (paper-fig4, carpet-lace, ...) or a .super.toml path", 0,
     "paper-fig4"},
    {"buffers", ParamType::number, "V, the number of buffers (V-variability), a whole number", 3},
    {"mode", ParamType::text,
     "attractor, tops (top addresses through a colour ramp), steal (colours of source) or measure",
     0, "tops"},
    {"source", ParamType::text, "Steal mode: the image colours are stolen from"},
    {"seed", ParamType::number, "Random seed, a whole number: the same seed gives the same frames",
     1},
    {"speed", ParamType::number, "Steps of the sequence per second: a new texture every 1/speed s",
     1},
    {"crossfade", ParamType::flag, "Blend each texture into the next instead of cutting", 1},
    {"rate", ParamType::number, "Frames per second to count by when the host gives no frame times",
     default_count_rate},
    {"loop", ParamType::number,
     "Seconds after which the sequence repeats, frame for frame: ceil(loop x speed) textures, "
     "the last fading into the first (0: never)",
     0},
};

// What the textures depend on (speed and crossfade only pick among them).
struct SequenceKey {
  std::string preset;
  int count = 3;
  TextureMode mode = TextureMode::tops;
  std::string source;
  std::uint64_t seed = 1;
  std::int64_t loop = 0;  // textures in a loop, 0 = none
  friend bool operator==(const SequenceKey&, const SequenceKey&) = default;
};

SequenceKey key_of(const ParamValues::Values& v) {
  SequenceKey k;
  k.preset = v.text(preset).empty() ? table[preset].text : v.text(preset);
  k.count = static_cast<int>(whole_number(v.number(buffers), "buffers", 1, 64));
  k.mode = parse_texture_mode(v.text(mode), "mode");
  k.source = v.text(source);
  if (k.mode == TextureMode::steal && k.source.empty())
    throw Error(ErrorKind::invalid_argument,
                "source: steal mode needs an image to steal colours from");
  k.seed = static_cast<std::uint64_t>(whole_number(v.number(seed), "seed", 0, 1LL << 53));
  const double seconds = v.number(loop), steps_per_second = v.number(speed);
  if (!(seconds >= 0 && seconds <= 86400))
    throw Error(ErrorKind::invalid_argument,
                "loop: must be 0..86400 seconds (got " + std::to_string(seconds) + ")");
  // Whole textures per loop, at least the speed asks for (a hair's rounding excepted).
  if (seconds > 0 && steps_per_second > 0 && std::isfinite(steps_per_second))
    k.loop = std::clamp<std::int64_t>(
        static_cast<std::int64_t>(std::ceil(seconds * steps_per_second - 1e-9)), 1, kMaxLoop);
  return k;
}

// A texture as the host's RGBA frame: grey (attractor) and BGR (the other modes, a BGR source)
// converted, 16-bit and float sources scaled to 8 bits, opaque.
void to_rgba(const cv::Mat& texture, cv::Mat& out) {
  cv::Mat eight = texture;
  if (texture.depth() == CV_16U) texture.convertTo(eight, CV_8U, 1.0 / 257);
  if (texture.depth() == CV_32F) texture.convertTo(eight, CV_8U, 255);
  switch (eight.channels()) {
    case 1:
      cv::cvtColor(eight, out, cv::COLOR_GRAY2RGBA);
      break;
    case 3:
      cv::cvtColor(eight, out, cv::COLOR_BGR2RGBA);
      break;
    default:
      cv::cvtColor(eight, out, cv::COLOR_BGRA2RGBA);
      break;
  }
}

class TextureInstance {
 public:
  TextureInstance(unsigned width, unsigned height)
      : size_(static_cast<int>(width), static_cast<int>(height)) {}

  ParamValues& params() { return values_; }

  // One frame at the host's `host_time`, in `unit` (host_clock.h: checked before it is trusted).
  void update(double host_time, TimeUnit unit, std::uint32_t* out) {
    if (out == nullptr) return;
    cv::Mat result(size_, CV_8UC4, out);
    if (!clock_) clock_.emplace(unit);
    const ParamValues::Values v = values_.values();
    // Every frame is counted, made or not: the count is the clock of a host without times.
    const HostClock::Reading time = clock_->next(host_time, v.number(rate));
    try {
      const double steps_per_second = v.number(speed);
      if (!(steps_per_second >= 0) || !std::isfinite(steps_per_second))
        throw Error(ErrorKind::invalid_argument, "speed: must be 0 or more steps per second (got " +
                                                     std::to_string(steps_per_second) + ")");
      frame_rate_parameter(v.number(rate));
      const SequenceKey key = key_of(v);
      sequence_for(key);
      if (time.counted && steps_per_second > 0)
        clock_reporter_.report(fmt::format(
            "the host gives no frame times; animating by frame count at {:g} fps", time.rate));
      double steps = time.seconds * steps_per_second;
      if (key.loop > 0) {
        // The place in the loop, as a fraction of it, on its whole number of textures.
        const double seconds = v.number(loop);
        double u = time.seconds / seconds;
        u -= std::floor(u);
        steps = u * static_cast<double>(key.loop);
      }
      StepPosition at = position_of_steps(steps);
      if (!v.flag(crossfade)) at.phase = 0;
      to_rgba(sequence_->frame_at(at), result);
      reporter_.clear();
    } catch (const std::exception& e) {
      reporter_.report(std::string(e.what()) + "; frames are black");
      result.setTo(cv::Scalar(0, 0, 0, 255));
    } catch (...) {
      reporter_.report("unexpected failure; frames are black");
      result.setTo(cv::Scalar(0, 0, 0, 255));
    }
  }

 private:
  void sequence_for(const SequenceKey& key) {
    if (sequence_ && key_ == key) return;
    if (failed_ && failed_->first == key) throw Error(ErrorKind::invalid_argument, failed_->second);
    try {
      TextureOptions o{.sampling = {.seed = key.seed}, .count = key.count, .mode = key.mode};
      o.loop = key.loop;
      if (!key.source.empty()) o.source = read_image(key.source).pixels;
      sequence_ = std::make_unique<TextureSequence>(load_superifs(key.preset).super, size_, o);
    } catch (const std::exception& e) {
      sequence_.reset();
      failed_.emplace(key, e.what());
      throw;
    }
    failed_.reset();
    key_ = key;
  }

  cv::Size size_;
  ParamValues values_{table};
  Reporter reporter_{plugin_name};
  Reporter clock_reporter_{plugin_name};  // once per instance (and per rate), never cleared
  std::optional<HostClock> clock_;        // made by the first frame, which shows who the host is
  SequenceKey key_;
  std::unique_ptr<TextureSequence> sequence_;
  std::optional<std::pair<SequenceKey, std::string>> failed_;
};

}  // namespace
}  // namespace ifsfx::frei0r

using ifsfx::frei0r::TextureInstance;

extern "C" {

// No global state: see ifsfx.cpp.
IFSFX_F0R_EXPORT int f0r_init() {
  return 1;
}
IFSFX_F0R_EXPORT void f0r_deinit() {}

IFSFX_F0R_EXPORT void f0r_get_plugin_info(f0r_plugin_info_t* info) {
  info->name = ifsfx::frei0r::plugin_name;
  info->author = "ifsfx";
  info->plugin_type = F0R_PLUGIN_TYPE_SOURCE;
  info->color_model = F0R_COLOR_MODEL_RGBA8888;
  info->frei0r_version = FREI0R_MAJOR_VERSION;
  info->major_version = 0;
  info->minor_version = 1;
  info->num_params = static_cast<int>(std::size(ifsfx::frei0r::table));
  info->explanation = "V-variable superfractal textures from a superIFS, one step per 1/speed s";
}

IFSFX_F0R_EXPORT void f0r_get_param_info(f0r_param_info_t* info, int index) {
  ifsfx::frei0r::describe(ifsfx::frei0r::table, info, index);
}

IFSFX_F0R_EXPORT f0r_instance_t f0r_construct(unsigned int width, unsigned int height) {
  try {
    return new TextureInstance(width, height);
  } catch (...) {
    return nullptr;
  }
}

IFSFX_F0R_EXPORT void f0r_destruct(f0r_instance_t instance) {
  delete static_cast<TextureInstance*>(instance);
}

IFSFX_F0R_EXPORT void f0r_set_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
  try {
    static_cast<TextureInstance*>(instance)->params().set(param, index);
  } catch (...) {
    // Out of memory: the parameter keeps its value.
  }
}

IFSFX_F0R_EXPORT void f0r_get_param_value(f0r_instance_t instance, f0r_param_t param, int index) {
  static_cast<TextureInstance*>(instance)->params().get(param, index);
}

IFSFX_F0R_EXPORT void f0r_update(f0r_instance_t instance, double time, const uint32_t*,
                                 uint32_t* outframe) {
  static_cast<TextureInstance*>(instance)->update(
      time, ifsfx::frei0r::host_time_unit(__builtin_return_address(0)), outframe);
}

}  // extern "C"
