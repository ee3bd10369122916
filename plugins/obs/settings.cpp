// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/settings.h"

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/view.h"

namespace ifsfx::obs {
namespace {

engine::Animate animate_of(const std::string& name) {
  if (name == "none") return engine::Animate::none;
  if (name == "drift") return engine::Animate::drift;
  if (name == "superifs") return engine::Animate::superifs;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("animate: must be none, drift or superifs (got {})", name));
}

Mode mode_of(const std::string& name) {
  if (name == "steal") return Mode::steal;
  if (name == "tops") return Mode::tops;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("mode: must be steal or tops (got {})", name));
}

}  // namespace

PluginSettings settings_of(const PropertyValues& v) {
  PluginSettings out;
  out.mode = mode_of(v.mode);
  engine::FractalSettings& s = out.engine;
  s.animate = animate_of(v.animate);
  const std::string preset = v.preset_file.empty() ? v.preset : v.preset_file;
  if (preset.empty()) throw Error(ErrorKind::invalid_argument, "preset: must be given (got none)");
  if (s.animate != engine::Animate::superifs) {  // a superIFS brings its own maps
    engine::Drawing F = engine::load_drawing(preset);
    if (!v.colouring.empty()) s.colouring = engine::colouring_for(v.colouring, F, "colouring");
    s.drawing = std::move(F);
  }
  if (!v.view.empty()) s.sampling.view = parse_box(v.view, "view");
  if (v.seed < 0)
    throw Error(ErrorKind::invalid_argument, fmt::format("seed: must be >= 0 (got {})", v.seed));
  s.sampling.seed = static_cast<std::uint64_t>(v.seed);
  s.exact = v.exact;
  s.mix = v.mix;
  s.background = engine::parse_background(v.background, "background");
  s.drift_amount = v.drift_amount;
  s.drift_speed = v.drift_speed;
  s.superifs = v.superifs;
  s.buffers = static_cast<int>(v.buffers);
  s.keyframe_interval = static_cast<int>(v.keyframe_interval);
  s.loop = v.loop;
  // A camera's frames come at its pace: an animation never holds one back for a late keyframe
  // (engine/map_schedule.h, "Live"; docs/obs.md).
  s.live = true;
  // `ifsfx filter`'s rule (check_filter_rules): a loop repeats an animation.
  if (s.loop > 0 && s.animate == engine::Animate::none)
    throw Error(ErrorKind::invalid_argument,
                "loop: repeats an animation; set animate to drift or superifs (got none)");
  if (out.mode == Mode::tops && s.animate != engine::Animate::none)
    throw Error(ErrorKind::invalid_argument,
                "animate: tops is one still picture of the preset; animate needs mode steal");
  return out;
}

void check_settings(const PluginSettings& settings) {
  const engine::FractalEngine engine(settings.engine);  // loads and checks, builds nothing
}

}  // namespace ifsfx::obs
