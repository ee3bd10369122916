// SPDX-License-Identifier: Apache-2.0
#include "ifs/detail/preconditions.h"

#include <cmath>

#include <fmt/format.h>

#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::detail {

void check_chaos_game(const ChaosGameInputs& in) {
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
  if (in.view) {
    const Box& v = *in.view;
    if (!(v.x1 > v.x0) || !(v.y1 > v.y0) || !std::isfinite(v.x0) || !std::isfinite(v.x1) ||
        !std::isfinite(v.y0) || !std::isfinite(v.y1))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("view: must be a rectangle x0 < x1, y0 < y1 of finite numbers "
                              "(got {},{},{},{})",
                              v.x0, v.y0, v.x1, v.y1));
  }
  if (!(in.margin >= 0) || !std::isfinite(in.margin))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("margin: must be a finite number ≥ 0 (got {})", in.margin));
}

}  // namespace ifsfx::detail
