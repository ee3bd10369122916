// SPDX-License-Identifier: Apache-2.0
#include "run/filter_options.h"

#include <map>

#include <fmt/format.h>

#include "ifs/error.h"
#include "run/arguments.h"

namespace ifsfx::app {

using engine::Animate;

void check_filter_rules(const FilterArgs& args) {
  check_loop_rule(args.fractal.engine.loop, args.animate);
}

void check_loop_rule(std::int64_t loop, Animate animate, const LoopRuleNames& names) {
  if (loop > 0 && animate == Animate::none)
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: repeats an animation; add {} or {}",
                                                         names.loop, names.drift, names.superifs));
}

}  // namespace ifsfx::app
