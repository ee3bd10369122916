// SPDX-License-Identifier: Apache-2.0
#include "run/filter_options.h"

#include <map>

#include "ifs/error.h"
#include "run/arguments.h"

namespace ifsfx::app {

using engine::Animate;

void check_filter_rules(const FilterArgs& args) {
  if (args.fractal.engine.loop > 0 && args.animate == Animate::none)
    throw Error(ErrorKind::invalid_argument,
                "--loop: repeats an animation; add --animate drift or --animate superifs");
}

}  // namespace ifsfx::app
