// SPDX-License-Identifier: Apache-2.0
#include "flame/render.h"

#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "flame/detail/render_chaos.h"
#include "flame/render_camera.h"
#include "flame/render_tone.h"
#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/view.h"

namespace ifsfx::flame {
namespace {

void require(bool ok, const char* what, const std::string& rule, double got) {
  if (!ok)
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: {} (got {})", what, rule, got));
}

void check_inputs(const Flame& f, double quality, const FlameRenderOptions& o) {
  if (f.xforms.empty())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("flame \"{}\": no xform to render", f.name));
  check_size({f.camera.width, f.camera.height}, "flame size");
  require(std::isfinite(quality) && quality > 0 && quality <= kMaxQuality, "quality",
          fmt::format("must be above 0 and at most {}", kMaxQuality), quality);
  require(std::isfinite(f.camera.scale) && f.camera.scale > 0, "scale", "must be positive",
          f.camera.scale);
  require(std::isfinite(f.camera.zoom) && std::abs(f.camera.zoom) <= 30, "zoom",
          "must be within ±30", f.camera.zoom);
  require(f.filtering.supersample >= 1 && f.filtering.supersample <= 16, "supersample",
          "must be 1 to 16", f.filtering.supersample);
  require(std::isfinite(f.filtering.filter_radius) && f.filtering.filter_radius >= 0 &&
              f.filtering.filter_radius <= 64,
          "filter", "must be 0 to 64 pixels", f.filtering.filter_radius);
  require(std::isfinite(f.filtering.estimator_radius) && f.filtering.estimator_radius >= 0 &&
              f.filtering.estimator_radius <= 64,
          "estimator_radius", "must be 0 to 64 pixels", f.filtering.estimator_radius);
  require(f.filtering.estimator_minimum >= 0, "estimator_minimum", "must be ≥ 0",
          f.filtering.estimator_minimum);
  require(std::isfinite(f.filtering.estimator_curve), "estimator_curve", "must be finite",
          f.filtering.estimator_curve);
  require(std::isfinite(f.tone.gamma) && f.tone.gamma > 0, "gamma", "must be positive",
          f.tone.gamma);
  require(std::isfinite(f.tone.contrast) && f.tone.contrast > 0, "contrast", "must be positive",
          f.tone.contrast);
  require(o.burn_in >= 0, "burn_in", "must be ≥ 0", o.burn_in);
}

// The flame with the options' size: the scale follows the width, so the framing is kept.
Flame resized(const Flame& flame, const FlameRenderOptions& o) {
  Flame f = flame;
  if (o.size) {
    check_size(*o.size, "size");
    f.camera.scale *= static_cast<double>(o.size->width) / flame.camera.width;
    f.camera.width = o.size->width;
    f.camera.height = o.size->height;
  }
  return f;
}

double coverage_of(const FlameHistogram& pixels) {
  std::size_t lit = 0;
  for (std::size_t i = 3; i < pixels.rgba.size(); i += 4) lit += pixels.rgba[i] > 0;
  return static_cast<double>(lit) / (static_cast<double>(pixels.rgba.size()) / 4);
}

}  // namespace

cv::Mat render_flame(const Flame& input, const FlameRenderOptions& options,
                     FlameRenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const Flame flame = resized(input, options);
  const double quality = options.quality.value_or(flame.quality);
  check_inputs(flame, quality, options);
  const int ss = flame.filtering.supersample;
  const SpatialKernel kernel =
      spatial_kernel(flame.filtering.filter_shape, flame.filtering.filter_radius, ss);
  const Camera& cam = flame.camera;
  // Samples per output pixel, × 4^zoom as flam3 takes them: a zoomed-in picture keeps its
  // density of points per flame-plane unit².
  const double samples = quality * std::exp2(2 * cam.zoom) * cam.width * cam.height;
  const auto progress = [&](double f) {
    if (options.progress) options.progress(0.9 * f);
  };
  detail::ChaosResult chaos =
      detail::run_chaos_game({.flame = &flame,
                              .raster = flame_raster(cam, ss, kernel.gutter),
                              .points = static_cast<std::uint64_t>(std::ceil(samples)),
                              .seed = options.seed,
                              .threads = options.threads,
                              .burn_in = options.burn_in,
                              .float_lanes = options.float_lanes,
                              .cancel = options.cancel,
                              .progress = progress});
  const FlameHistogram dense =
      density_estimate(std::move(chaos.histogram), flame.filtering, ss,
                       log_scale(flame, ss, quality), options.threads, options.cancel);
  const FlameHistogram pixels =
      spatial_filter(dense, kernel, ss, cam.width, cam.height, options.threads, options.cancel);
  cv::Mat out = display(pixels, flame.tone, options.channels, options.depth, options.threads);
  if (options.progress) options.progress(1.0);
  if (stats) {
    stats->points = static_cast<std::uint64_t>(std::ceil(samples));
    stats->reseeded = chaos.reseeded;
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->coverage = coverage_of(pixels);
  }
  return out;
}

}  // namespace ifsfx::flame
