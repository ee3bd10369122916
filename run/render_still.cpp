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

// A flame's measure: the flame look (render_flame), float BGR as the IFS measure.
cv::Mat flame_measure(const flame::Flame& F, const StillJob& job, RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  flame::FlameRenderStats flame_stats;
  cv::Mat image = flame::render_flame(F,
                                      {.size = job.size,
                                       .quality = job.options.sampling.quality,
                                       .seed = job.options.sampling.seed,
                                       .threads = job.options.sampling.threads,
                                       .cancel = job.options.sampling.cancel,
                                       .depth = CV_32F},
                                      &flame_stats);
  stats = {.points = flame_stats.points,
           .seconds = seconds_since(start),
           .coverage = flame_stats.coverage,
           .view = flame::flame_viewport(F, job.size).view};
  return image;
}

}  // namespace

StillResult render_still(const engine::Drawing& drawing, const StillJob& job) {
  // A flame draws its attractor, tops and steal through the chaos game (flame/flame_chaos.h);
  // only tops and steal follow addresses, where the exact descent would need inverse maps.
  const auto* as_flame = std::get_if<flame::Flame>(&drawing);
  if (as_flame)
    flame::check_flame_chaos(job.options.sampling,
                             job.exact && render_mode_info(job.mode).map_method);
  StillResult result;
  switch (job.mode) {
    case RenderMode::attractor:
      result.image =
          as_flame
              ? flame::flame_attractor(*as_flame, job.size, job.options.sampling, &result.stats)
              : laid_out(
                    render_attractor(std::get<Ifs>(drawing), job.size, job.options, &result.stats),
                    job.layout);
      break;
    case RenderMode::measure:
      result.image = as_flame ? flame_measure(*as_flame, job, result.stats)
                              : laid_out(render_measure(std::get<Ifs>(drawing), job.size,
                                                        job.options, &result.stats),
                                         job.layout);
      break;
    case RenderMode::tops:
      result.image = tops_still(drawing, job, result.stats);
      break;
    case RenderMode::steal:
      result.image = steal_still(drawing, job, result);
      break;
  }
  return result;
}

}  // namespace ifsfx::app
