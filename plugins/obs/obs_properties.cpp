// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/obs_properties.h"

#include <climits>
#include <exception>

#include "engine/drift.h"
#include "ifs/preset.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace ifsfx::obs {
namespace {

const char* text(const char* key) {
  return obs_module_text(key);
}

// Checks the dialog's values as they are changed, so that a preset that does not load says why
// at once, in the status line, while frames keep the last good settings.
bool show_status(obs_properties_t* props, obs_property_t*, obs_data_t* data) {
  std::string message;
  try {
    check_settings(settings_of(read_values(data)));
  } catch (const std::exception& e) {
    message = e.what();
  }
  obs_property_t* status = obs_properties_get(props, kStatus);
  obs_property_set_description(status, message.c_str());
  obs_property_set_visible(status, !message.empty());
  return true;
}

void add_fractal(obs_properties_t* p) {
  obs_property_t* preset = obs_properties_add_list(
      p, "preset", text("Preset"), OBS_COMBO_TYPE_EDITABLE, OBS_COMBO_FORMAT_STRING);
  for (const PresetSummary& s : list_shipped_presets())
    obs_property_list_add_string(preset, s.name.c_str(), s.name.c_str());
  obs_properties_add_path(
      p, "preset_file", text("PresetFile"), OBS_PATH_FILE,
      "IFS presets and flames (*.toml *.ifs *.csv *.flame *.flam3);;All files (*.*)", nullptr);
  obs_property_t* mode = obs_properties_add_list(p, "mode", text("Mode"), OBS_COMBO_TYPE_LIST,
                                                 OBS_COMBO_FORMAT_STRING);
  obs_property_list_add_string(mode, text("Mode.Steal"), "steal");
  obs_property_list_add_string(mode, text("Mode.Tops"), "tops");
  obs_properties_add_text(p, "colouring", text("Colouring"), OBS_TEXT_DEFAULT);
  obs_properties_add_text(p, "view", text("View"), OBS_TEXT_DEFAULT);
  obs_properties_add_float_slider(p, "mix", text("Mix"), 0, 1, 0.01);
  obs_properties_add_text(p, "background", text("Background"), OBS_TEXT_DEFAULT);
  obs_properties_add_int(p, "seed", text("Seed"), 0, INT_MAX, 1);
  obs_properties_add_bool(p, "exact", text("Exact"));
}

void add_animation(obs_properties_t* p) {
  obs_property_t* animate = obs_properties_add_list(p, "animate", text("Animate"),
                                                    OBS_COMBO_TYPE_LIST, OBS_COMBO_FORMAT_STRING);
  obs_property_list_add_string(animate, text("Animate.None"), "none");
  obs_property_list_add_string(animate, text("Animate.Drift"), "drift");
  obs_property_list_add_string(animate, text("Animate.SuperIfs"), "superifs");
  obs_properties_add_float(p, "drift_amount", text("DriftAmount"), 0, engine::kMaxDriftAmount,
                           0.01);
  obs_properties_add_float(p, "drift_speed", text("DriftSpeed"), 0, engine::kMaxDriftSpeed, 0.01);
  obs_property_t* superifs = obs_properties_add_list(
      p, "superifs", text("SuperIfs"), OBS_COMBO_TYPE_EDITABLE, OBS_COMBO_FORMAT_STRING);
  for (const SuperIfsSummary& s : list_shipped_superifs())
    obs_property_list_add_string(superifs, s.name.c_str(), s.name.c_str());
  obs_properties_add_int(p, "buffers", text("Buffers"), 1, 64, 1);
  obs_properties_add_int(p, "keyframe_interval", text("KeyframeInterval"), 1, 100000, 1);
  obs_properties_add_int(p, "loop", text("Loop"), 0, static_cast<int>(kMaxLoop), 1);
}

}  // namespace

void set_defaults(obs_data_t* d) {
  const PropertyValues v;
  obs_data_set_default_string(d, "preset", v.preset.c_str());
  obs_data_set_default_string(d, "preset_file", v.preset_file.c_str());
  obs_data_set_default_string(d, "mode", v.mode.c_str());
  obs_data_set_default_string(d, "colouring", v.colouring.c_str());
  obs_data_set_default_string(d, "view", v.view.c_str());
  obs_data_set_default_double(d, "mix", v.mix);
  obs_data_set_default_string(d, "background", v.background.c_str());
  obs_data_set_default_string(d, "animate", v.animate.c_str());
  obs_data_set_default_double(d, "drift_amount", v.drift_amount);
  obs_data_set_default_double(d, "drift_speed", v.drift_speed);
  obs_data_set_default_string(d, "superifs", v.superifs.c_str());
  obs_data_set_default_int(d, "buffers", v.buffers);
  obs_data_set_default_int(d, "keyframe_interval", v.keyframe_interval);
  obs_data_set_default_int(d, "loop", v.loop);
  obs_data_set_default_int(d, "seed", v.seed);
  obs_data_set_default_bool(d, "exact", v.exact);
}

PropertyValues read_values(obs_data_t* d) {
  PropertyValues v;
  v.preset = obs_data_get_string(d, "preset");
  v.preset_file = obs_data_get_string(d, "preset_file");
  v.mode = obs_data_get_string(d, "mode");
  v.colouring = obs_data_get_string(d, "colouring");
  v.view = obs_data_get_string(d, "view");
  v.mix = obs_data_get_double(d, "mix");
  v.background = obs_data_get_string(d, "background");
  v.animate = obs_data_get_string(d, "animate");
  v.drift_amount = obs_data_get_double(d, "drift_amount");
  v.drift_speed = obs_data_get_double(d, "drift_speed");
  v.superifs = obs_data_get_string(d, "superifs");
  v.buffers = obs_data_get_int(d, "buffers");
  v.keyframe_interval = obs_data_get_int(d, "keyframe_interval");
  v.loop = obs_data_get_int(d, "loop");
  v.seed = obs_data_get_int(d, "seed");
  v.exact = obs_data_get_bool(d, "exact");
  return v;
}

obs_properties_t* make_properties(const std::string& status) {
  obs_properties_t* p = obs_properties_create();
  obs_property_t* line = obs_properties_add_text(p, kStatus, status.c_str(), OBS_TEXT_INFO);
  obs_property_text_set_info_type(line, OBS_TEXT_INFO_ERROR);
  obs_property_set_visible(line, !status.empty());
  add_fractal(p);
  add_animation(p);
  for (const char* name : {"preset", "preset_file", "mode", "colouring", "view", "background",
                           "animate", "superifs", "loop"})
    obs_property_set_modified_callback(obs_properties_get(p, name), show_status);
  return p;
}

}  // namespace ifsfx::obs
