// SPDX-License-Identifier: Apache-2.0
#include "run/fit_run.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/utf8.h"
#include "ifs/view.h"

namespace ifsfx::app {

// The working raster's side from "S" or "SxS".
int working_size(const std::string& text) {
  if (text.find('x') == std::string::npos) {
    int side = 0;
    try {
      std::size_t used = 0;
      side = std::stoi(text, &used);
      if (used != text.size()) side = 0;
    } catch (const std::exception&) {
      side = 0;
    }
    if (side <= 0)
      throw Error(ErrorKind::parse, fmt::format("--size: expected S or SxS (got '{}')", text));
    return side;
  }
  const cv::Size size = parse_size(text, "--size");
  if (size.width != size.height)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--size: the working raster is square (got {})", text));
  return size.width;
}

void check_fit_maps(int maps, const std::string& what) {
  if (maps < 1 || maps > 32)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the number of maps must be in 1..32 (got {})", what, maps));
}

void check_fit_budgets(double max_seconds, long max_evaluations, const FitBudgetNames& names) {
  if (!(max_seconds >= 0 && max_seconds <= kMaxFitSeconds))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: must be in [0, {}] (got {})", names.seconds, kMaxFitSeconds, max_seconds));
  if (max_evaluations < 2 || max_evaluations > kMaxFitEvaluations)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: must be in 2..{} (got {})", names.evaluations, kMaxFitEvaluations,
                            max_evaluations));
}

void check_fit_shares(double reseed_share, double grow_share, const FitShareNames& names) {
  for (const auto& [value, name] :
       {std::pair{reseed_share, &names.reseed}, {grow_share, &names.grow}})
    if (!(value >= 0 && value <= kMaxFitShare))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: must be in [0, {}] (got {})", *name, kMaxFitShare, value));
}

cv::Mat fit_raster(const FitArgs& args) {
  collage::TargetOptions target_options;
  target_options.threshold = args.threshold;
  target_options.invert = args.invert;
  const cv::Mat mask = collage::load_target(args.target, target_options);
  return collage::working_raster(mask, {.size = working_size(args.size)});
}

cv::Mat fit_fine_raster(const FitArgs& args) {
  collage::TargetOptions target_options;
  target_options.threshold = args.threshold;
  target_options.invert = args.invert;
  const cv::Mat mask = collage::load_target(args.target, target_options);
  return collage::working_raster(mask, {.size = std::min(4 * working_size(args.size), 2048)});
}

collage::FitOptions fit_options(const FitArgs& args, const CancelToken& cancel) {
  collage::FitOptions options;
  options.maps = args.maps;
  options.seed = args.seed;
  options.init = args.init;
  options.method = args.method;
  options.max_seconds = args.max_seconds;
  options.max_evaluations = args.max_evaluations;
  options.reseed_share = args.reseed_share;
  options.grow_share = args.grow_share;
  options.threads = args.threads;
  options.cancel = cancel;
  options.name = valid_utf8(std::filesystem::path(args.target).stem().string());
  return options;
}

std::string fit_summary(const FitArgs& args, const collage::FitResult& result) {
  const collage::CollageReport& r = result.report;
  const std::string fine =
      r.fine_size > 0 ? fmt::format(" ({}²: {:.3f})", r.fine_size, r.fine_iou) : std::string();
  return fmt::format("fitted by ifsfx fit to {}: IoU {:.3f}{}, s {:.3f}", args.target, r.iou, fine,
                     r.contraction);
}

}  // namespace ifsfx::app
