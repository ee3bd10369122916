// SPDX-License-Identifier: Apache-2.0
// A frei0r filter that only reports its host's clock: each f0r_update prints "time=T" (T as
// passed, %.17g) on stderr and copies the frame. plugins_e2e.sh host_times runs it in FFmpeg, melt
// and GStreamer to show what each passes — the facts host_clock.h is built on.
#include <cstdio>
#include <cstring>

#define PROBE_EXPORT __attribute__((visibility("default")))

extern "C" {
#include <frei0r.h>

PROBE_EXPORT int f0r_init() {
  return 1;
}
PROBE_EXPORT void f0r_deinit() {}
PROBE_EXPORT void f0r_get_plugin_info(f0r_plugin_info_t* info) {
  info->name = "ifsfx-time-probe";
  info->author = "ifsfx tests";
  info->plugin_type = F0R_PLUGIN_TYPE_FILTER;
  info->color_model = F0R_COLOR_MODEL_RGBA8888;
  info->frei0r_version = FREI0R_MAJOR_VERSION;
  info->major_version = 0;
  info->minor_version = 1;
  info->num_params = 0;
  info->explanation = "Prints f0r_update's time";
}
PROBE_EXPORT void f0r_get_param_info(f0r_param_info_t*, int) {}
struct Probe {
  unsigned pixels;
};
PROBE_EXPORT f0r_instance_t f0r_construct(unsigned w, unsigned h) {
  return new Probe{w * h};
}
PROBE_EXPORT void f0r_destruct(f0r_instance_t p) {
  delete static_cast<Probe*>(p);
}
PROBE_EXPORT void f0r_set_param_value(f0r_instance_t, f0r_param_t, int) {}
PROBE_EXPORT void f0r_get_param_value(f0r_instance_t, f0r_param_t, int) {}
PROBE_EXPORT void f0r_update(f0r_instance_t p, double time, const uint32_t* in, uint32_t* out) {
  std::fprintf(stderr, "time=%.17g\n", time);
  if (in != nullptr && out != nullptr && in != out)
    std::memcpy(out, in, static_cast<std::size_t>(static_cast<Probe*>(p)->pixels) * 4);
}
}  // extern "C"
