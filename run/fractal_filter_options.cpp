// SPDX-License-Identifier: Apache-2.0
#include "run/fractal_filter_options.h"

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "run/arguments.h"
#include "superifs/texture.h"

namespace ifsfx::app {

void refuse_named_exact(const engine::Drawing& drawing, bool exact, bool named,
                        std::string_view name) {
  if (named && exact && std::holds_alternative<flame::Flame>(drawing))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the exact descent follows inverse maps, and a flame's xforms "
                            "have none; a flame filters through the chaos game (got {})",
                            name, engine::name_of(drawing)));
}

engine::FractalSettings FractalFilterArgs::settings(std::vector<std::string>* warnings) const {
  engine::Drawing F = engine::load_drawing(preset, {}, warnings);
  std::optional<Ifs> G;
  if (!colouring.empty()) G = engine::colouring_for(colouring, F, "colouring");
  return settings_of(std::move(F), std::move(G));
}

engine::FractalSettings FractalFilterArgs::settings_of(engine::Drawing drawing,
                                                       std::optional<Ifs> colouring_ifs) const {
  refuse_named_exact(drawing, engine.exact, exact_given, exact_name);
  engine::FractalSettings s = engine;
  s.drawing = std::move(drawing);
  s.colouring = std::move(colouring_ifs);
  s.sampling.view = view_option(view);
  s.background = engine::parse_background(background);
  return s;
}

}  // namespace ifsfx::app
