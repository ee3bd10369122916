// SPDX-License-Identifier: Apache-2.0
#include "run/render_still.h"

#include <chrono>

#include "flame/flame_chaos.h"
#include "flame/render.h"
#include "ifs/error.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"
#include "run/seamless_options.h"

namespace ifsfx::app {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

cv::Mat tops_still(const engine::Drawing& F, const StillJob& job, RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  TopsPictureStats tops;
  const cv::Mat image = engine::tops_picture(
      F, job.size,
      {.sampling = job.options.sampling, .exact = job.exact, .second_symbol = job.second_symbol},
      job.background, job.alpha, &tops);
  stats = {.points = tops.points,
           .seconds = seconds_since(start),
           .coverage = tops.coverage,
           .view = tops.view};
  return laid_out(image, job.layout);
}

// The steal map of F through G, laid out (a seamless map colours the whole picture), applied to
// the source.
cv::Mat steal_still(const engine::Drawing& F, const StillJob& job, StillResult& result) {
  if (job.source.empty())
    throw Error(ErrorKind::invalid_argument, "source: the steal mode needs a source image");
  const Ifs G = job.colouring ? *job.colouring : default_colouring(engine::map_count(F));
  const StealMapOptions options{.sampling = job.options.sampling, .exact = job.exact};
  StealMap map = engine::steal_map(F, G, job.size, options, &result.steal);
  if (options.sampling.seamless) map = tile_picture(map, job.layout);
  const cv::Mat coloured =
      apply(map, job.source,
            {.background = background_scalar(job.background, job.source.depth()),
             .threads = options.sampling.threads});
  result.stats = {.points = result.steal.points,
                  .seconds = result.steal.seconds,
                  .coverage = result.steal.coverage,
                  .view = result.steal.view};
  cv::Mat image = with_coverage_alpha(coloured, map.coverage, job.alpha);
  result.map = std::move(map);
  return image;
}

// A flame's still: its xforms through the chaos game (flame/flame_chaos.h) for the attractor,
// tops and steal; its measure is the flame look (render_flame, float BGR as the IFS measure).
StillResult flame_still(const flame::Flame& F, const StillJob& job) {
  // Only tops and steal follow addresses, where the exact descent would need inverse maps.
  const bool descent = job.exact && render_mode_info(job.mode).map_method;
  flame::check_flame_chaos(job.options.sampling, descent);
  StillResult result;
  switch (job.mode) {
    case RenderMode::attractor:
      result.image = flame::flame_attractor(F, job.size, job.options.sampling, &result.stats);
      break;
    case RenderMode::measure: {
      const auto start = std::chrono::steady_clock::now();
      flame::FlameRenderStats stats;
      result.image = flame::render_flame(F,
                                         {.size = job.size,
                                          .quality = job.options.sampling.quality,
                                          .seed = job.options.sampling.seed,
                                          .threads = job.options.sampling.threads,
                                          .cancel = job.options.sampling.cancel,
                                          .depth = CV_32F},
                                         &stats);
      result.stats = {.points = stats.points,
                      .seconds = seconds_since(start),
                      .coverage = stats.coverage,
                      .view = flame::flame_viewport(F, job.size).view};
      break;
    }
    case RenderMode::tops:
      result.image = tops_still(F, job, result.stats);
      break;
    case RenderMode::steal:
      result.image = steal_still(F, job, result);
      break;
  }
  return result;
}

}  // namespace

StillResult render_still(const engine::Drawing& drawing, const StillJob& job) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) return flame_still(*f, job);
  const Ifs& F = std::get<Ifs>(drawing);
  StillResult result;
  switch (job.mode) {
    case RenderMode::attractor:
      result.image =
          laid_out(render_attractor(F, job.size, job.options, &result.stats), job.layout);
      break;
    case RenderMode::measure:
      result.image = laid_out(render_measure(F, job.size, job.options, &result.stats), job.layout);
      break;
    case RenderMode::tops:
      result.image = tops_still(F, job, result.stats);
      break;
    case RenderMode::steal:
      result.image = steal_still(F, job, result);
      break;
  }
  return result;
}

}  // namespace ifsfx::app
