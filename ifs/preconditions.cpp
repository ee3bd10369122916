// SPDX-License-Identifier: Apache-2.0
#include "ifs/detail/preconditions.h"

#include <cmath>

#include <fmt/format.h>

#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::detail {

void check_chaos_game(const ChaosGameInputs& given) {
  ChaosGameInputs in = given;
  if (in.sampling) {
    in.threads = in.sampling->threads;
    in.quality = in.sampling->quality;
    in.view = in.sampling->view;
    in.margin = in.sampling->margin;
  }
  const std::string& name = !in.name.empty() ? in.name : !in.ifs.name.empty() ? in.ifs.name : "ifs";
  validate(in.ifs, name, {.allow_expansive = true, .require_contraction = in.contracting});
  resolve_threads(in.threads);
  if (in.burn_in < 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("burn_in: must be ≥ 0, 0 for the default (got {})", in.burn_in));
  if (in.quality && !(*in.quality > 0 && *in.quality <= kMaxQuality))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("quality: must be a positive number of points per pixel, at most {:g} "
                            "(got {})",
                            kMaxQuality, *in.quality));
  if (in.size) check_size(*in.size, "size");
  if (in.view) check_view(*in.view);
  if (!(in.margin >= 0) || !std::isfinite(in.margin))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("margin: must be a finite number ≥ 0 (got {})", in.margin));
}

}  // namespace ifsfx::detail
