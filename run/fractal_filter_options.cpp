// SPDX-License-Identifier: Apache-2.0
#include "run/fractal_filter_options.h"

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "run/arguments.h"
#include "superifs/texture.h"

namespace ifsfx::app {

engine::FractalSettings FractalFilterArgs::settings(std::vector<std::string>* warnings) const {
  engine::Drawing F = engine::load_drawing(preset, {}, warnings);
  // A flame's steal map always comes from the chaos game: a named --exact would do nothing.
  if (exact_given && engine.exact && std::holds_alternative<flame::Flame>(F))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--exact: the exact descent follows inverse maps, and a flame's xforms "
                            "have none; a flame filters through the chaos game (got {})",
                            preset));
  std::optional<Ifs> G;
  if (!colouring.empty()) G = engine::colouring_for(colouring, F, "colouring");
  return settings_of(std::move(F), std::move(G));
}

engine::FractalSettings FractalFilterArgs::settings_of(engine::Drawing drawing,
                                                       std::optional<Ifs> colouring_ifs) const {
  engine::FractalSettings s = engine;
  s.drawing = std::move(drawing);
  s.colouring = std::move(colouring_ifs);
  s.sampling.view = view_option(view);
  s.background = engine::parse_background(background);
  return s;
}

}  // namespace ifsfx::app
