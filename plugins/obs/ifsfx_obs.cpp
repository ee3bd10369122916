// SPDX-License-Identifier: Apache-2.0
// The `ifsfx fractal` filter of OBS Studio: the fractal filter of `ifsfx filter` (paper §6) on a
// webcam or media source. A thin door: the dialog's values become one PluginSettings
// (plugins/obs/settings.h), every frame goes through one FilterWorker (plugins/obs/filter_worker.h)
// off OBS's video thread, whose pictures are engine::FractalEngine's — no mathematics here.
//
// An async filter (OBS_SOURCE_ASYNC_VIDEO): frames arrive in CPU memory in the source's format
// (NV12, I420, YUY2, UYVY, RGBA, BGRA, BGRX, I444 are filtered; any other passes through) and the
// picture is written back into the same frame. Settings that do not work (an unknown preset, a
// bad view) show their one-line message in the dialog and keep the last good picture.
#include <algorithm>
#include <exception>
#include <iterator>
#include <memory>
#include <optional>

#include <obs-module.h>

#include "plugins/obs/filter_worker.h"
#include "plugins/obs/obs_properties.h"
#include "plugins/obs/settings.h"

OBS_DECLARE_MODULE()
OBS_MODULE_USE_DEFAULT_LOCALE("ifsfx-obs", "en-US")

namespace ifsfx::obs {
namespace {

std::optional<PixelFormat> format_of(video_format format) {
  switch (format) {
    case VIDEO_FORMAT_NV12:
      return PixelFormat::nv12;
    case VIDEO_FORMAT_I420:
      return PixelFormat::i420;
    case VIDEO_FORMAT_YUY2:
      return PixelFormat::yuy2;
    case VIDEO_FORMAT_UYVY:
      return PixelFormat::uyvy;
    case VIDEO_FORMAT_RGBA:
      return PixelFormat::rgba;
    case VIDEO_FORMAT_BGRA:
      return PixelFormat::bgra;
    case VIDEO_FORMAT_BGRX:
      return PixelFormat::bgrx;
    case VIDEO_FORMAT_I444:
      return PixelFormat::i444;
    default:
      return std::nullopt;
  }
}

// OBS's video rate: the animation counts frames by it, as `ifsfx filter --fps` does.
double video_rate() {
  obs_video_info info{};
  if (!obs_get_video_info(&info) || info.fps_den == 0 || info.fps_num == 0) return 30;
  return static_cast<double>(info.fps_num) / info.fps_den;
}

struct Filter {
  obs_source_t* source;
  FilterWorker worker{video_rate()};
};

void update(void* data, obs_data_t* settings) {
  auto* self = static_cast<Filter*>(data);
  try {
    const PluginSettings s = settings_of(read_values(settings));
    check_settings(s);
    self->worker.configure(s);
  } catch (const std::exception& e) {
    self->worker.reject(e.what());
    blog(LOG_WARNING, "[ifsfx-obs] '%s': %s", obs_source_get_name(self->source), e.what());
  }
}

void* create(obs_data_t* settings, obs_source_t* source) {
  try {
    auto* self = new Filter{source};
    update(self, settings);
    return self;
  } catch (const std::exception& e) {
    blog(LOG_ERROR, "[ifsfx-obs] cannot start: %s", e.what());
    return nullptr;
  }
}

void destroy(void* data) {
  auto* self = static_cast<Filter*>(data);
  const WorkerStats s = self->worker.stats();
  blog(LOG_INFO, "[ifsfx-obs] '%s': %lld frames, %lld pictures, %lld dropped, %lld repeated",
       obs_source_get_name(self->source), static_cast<long long>(s.frames),
       static_cast<long long>(s.filtered), static_cast<long long>(s.dropped),
       static_cast<long long>(s.repeated));
  delete self;
}

obs_source_frame* filter_video(void* data, obs_source_frame* frame) {
  const std::optional<PixelFormat> format = format_of(frame->format);
  if (!format) return frame;
  try {
    FrameData f;
    f.format = *format;
    f.size = cv::Size(static_cast<int>(frame->width), static_cast<int>(frame->height));
    std::copy(std::begin(frame->color_matrix), std::end(frame->color_matrix), f.yuv.matrix.begin());
    std::copy(std::begin(frame->color_range_min), std::end(frame->color_range_min),
              f.yuv.range_min.begin());
    std::copy(std::begin(frame->color_range_max), std::end(frame->color_range_max),
              f.yuv.range_max.begin());
    f.flip = frame->flip;
    f.timestamp = frame->timestamp;
    f.planes = wrap_planes(*format, f.size, frame->data, frame->linesize);
    static_cast<Filter*>(data)->worker.exchange(f);
  } catch (const std::exception& e) {
    blog(LOG_WARNING, "[ifsfx-obs] %s", e.what());
  }
  return frame;
}

obs_properties_t* properties(void* data) {
  return make_properties(data ? static_cast<Filter*>(data)->worker.status() : std::string());
}

obs_source_info filter_info() {
  obs_source_info info{};
  info.id = "ifsfx_fractal_filter";
  info.type = OBS_SOURCE_TYPE_FILTER;
  info.output_flags = OBS_SOURCE_VIDEO | OBS_SOURCE_ASYNC;
  info.get_name = [](void*) { return obs_module_text("FilterName"); };
  info.create = create;
  info.destroy = destroy;
  info.update = update;
  info.get_defaults = set_defaults;
  info.get_properties = properties;
  info.filter_video = filter_video;
  return info;
}

}  // namespace
}  // namespace ifsfx::obs

extern "C" {

bool obs_module_load(void) {
  const obs_source_info info = ifsfx::obs::filter_info();
  obs_register_source(&info);
  return true;
}

const char* obs_module_description(void) {
  return "ifsfx: the fractal filter of `ifsfx filter` (colour stealing) for webcams and media";
}

}  // extern "C"
