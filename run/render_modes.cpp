// SPDX-License-Identifier: Apache-2.0
#include "run/render_modes.h"

#include <array>
#include <cctype>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {
namespace {

constexpr std::array kModes{
    RenderModeInfo{
        .mode = RenderMode::attractor, .name = "attractor", .help = "the set", .flames = true},
    RenderModeInfo{.mode = RenderMode::measure,
                   .name = "measure",
                   .help = "log-density of the invariant measure, coloured by map",
                   .flames = true},
    RenderModeInfo{.mode = RenderMode::tops,
                   .name = "tops",
                   .help = "each pixel coloured by the first symbol of its top address",
                   .map_method = true,
                   .second_symbol = true,
                   .background = true,
                   .flames = true},
    RenderModeInfo{.mode = RenderMode::steal,
                   .name = "steal",
                   .help = "colours stolen from --source (fractal tops, colour stealing)",
                   .source = true,
                   .colouring = true,
                   .save_map = true,
                   .map_method = true,
                   .background = true,
                   .flames = true},
};

// "tops or steal": the modes for which `takes` holds.
std::string modes_taking(bool RenderModeInfo::*takes) {
  std::string text;
  int count = 0, total = 0;
  for (const RenderModeInfo& info : kModes) total += info.*takes;
  for (const RenderModeInfo& info : kModes) {
    if (!(info.*takes)) continue;
    text += count == 0 ? "" : count + 1 == total ? " or " : ", ";
    text += info.name;
    ++count;
  }
  return text;
}

}  // namespace

std::span<const RenderModeInfo> render_modes() {
  return kModes;
}

const RenderModeInfo& render_mode_info(RenderMode mode) {
  for (const RenderModeInfo& info : kModes)
    if (info.mode == mode) return info;
  throw Error(ErrorKind::invalid_argument, "mode: not a render mode");
}

std::string render_mode_names() {
  std::string text;
  for (std::size_t i = 0; i < kModes.size(); ++i)
    text += std::string(i == 0 ? "" : i + 1 == kModes.size() ? " or " : ", ") + kModes[i].name;
  return text;
}

RenderMode parse_render_mode(const std::string& text, const std::string& what) {
  std::string key = text;
  for (auto& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  for (const RenderModeInfo& info : kModes)
    if (key == info.name) return info.mode;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: {} (got '{}')", what, render_mode_names(), text));
}

void check_flame_mode(RenderMode mode, const std::string& mode_word) {
  if (!render_mode_info(mode).flames)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{} {}: a flame renders in mode {} (got a flame)", mode_word,
                            to_string(mode), modes_taking(&RenderModeInfo::flames)));
}

void check_mode_options(RenderMode mode, const ModeOptions& options, const std::string& mode_word) {
  const RenderModeInfo& info = render_mode_info(mode);
  const auto refuse = [&](const ModeOption& option, bool RenderModeInfo::*takes) {
    if (option.given && !(info.*takes))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: only with {} {} (got {} {})", option.name, mode_word,
                              modes_taking(takes), mode_word, info.name));
  };
  refuse(options.source, &RenderModeInfo::source);
  refuse(options.colouring, &RenderModeInfo::colouring);
  refuse(options.save_map, &RenderModeInfo::save_map);
  refuse(options.second_symbol, &RenderModeInfo::second_symbol);
  refuse(options.map_method, &RenderModeInfo::map_method);
  refuse(options.background, &RenderModeInfo::background);
  if (info.source && !options.source.given)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: {} {} needs a source image", options.source.name, mode_word, info.name));
}

}  // namespace ifsfx::app
