// SPDX-License-Identifier: Apache-2.0
#include "run/render_still.h"

#include <chrono>

#include "ifs/error.h"
#include "ifs/steal_picture.h"
#include "ifs/tops.h"
#include "run/seamless_options.h"

namespace ifsfx::app {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

cv::Mat tops_still(const Ifs& F, const StillJob& job, RenderStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  TopsPictureStats tops;
  const cv::Mat image = tops_picture(
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
cv::Mat steal_still(const Ifs& F, const StillJob& job, StillResult& result) {
  if (job.source.empty())
    throw Error(ErrorKind::invalid_argument, "source: the steal mode needs a source image");
  const Ifs G = job.colouring ? *job.colouring : default_colouring(F.size());
  const StealMapOptions options{.sampling = job.options.sampling, .exact = job.exact};
  StealMap map = compute_steal_map(F, G, job.size, options, &result.steal);
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

}  // namespace

StillResult render_still(const Ifs& F, const StillJob& job) {
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
