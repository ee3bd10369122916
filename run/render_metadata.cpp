// SPDX-License-Identifier: Apache-2.0
#include "run/render_metadata.h"

#include <fmt/format.h>

namespace ifsfx::app {

std::vector<std::pair<std::string, std::string>> render_metadata(const IfsPreset& preset,
                                                                 const std::string& mode,
                                                                 std::uint64_t seed,
                                                                 const Box& view) {
  return {
      {"ifsfx:preset", preset.text},
      {"ifsfx:preset_name", preset.ifs.name},
      {"ifsfx:mode", mode},
      {"ifsfx:seed", std::to_string(seed)},
      {"ifsfx:view", fmt::format("{},{},{},{}", view.x0, view.y0, view.x1, view.y1)},
  };
}

std::vector<std::pair<std::string, std::string>> flame_render_metadata(const std::string& name,
                                                                       const std::string& mode,
                                                                       std::uint64_t seed) {
  const std::string mode_flag = mode == "measure" ? "" : fmt::format(" --mode {}", mode);
  return {{"ifsfx:flame", name},
          {"ifsfx:mode", mode},
          {"ifsfx:seed", std::to_string(seed)},
          {"ImageDescription", fmt::format("ifsfx render {}{} --seed {}", name, mode_flag, seed)}};
}

}  // namespace ifsfx::app
