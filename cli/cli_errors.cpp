// SPDX-License-Identifier: Apache-2.0
#include "cli/cli_errors.h"

#include <string_view>
#include <utility>

namespace ifsfx::app {
namespace {

// Library parameter → flag, for the parameters the subcommands take under another name.
constexpr std::pair<std::string_view, std::string_view> kFlags[] = {
    {"size × supersample", "--size × --supersample"},
    {"size × tiles", "--size × --tiles"},
    {"tiles", "--tiles"},
    {"tile offset", "--tile-offset"},
    {"quality", "--quality"},
    {"supersample", "--supersample"},
    {"gamma", "--gamma"},
    {"brightness", "--brightness"},
    {"threads", "--threads"},
    {"size", "--size"},
    {"view", "--view"},
    {"margin", "--margin"},
    {"count", "-V"},
    {"steps", "--steps"},
    {"source", "--source"},
    {"mode", "--mode"},
    {"max_seconds", "--max-seconds"},
    {"threshold", "--threshold"},
    {"frames", "--frames"},
    {"background", "--background"},
    {"mix", "--mix"},
    {"keyframe interval", "--keyframe-interval"},
    {"colouring", "--colouring"},
    {"drift amount", "--drift-amount"},
    {"drift speed", "--drift-speed"},
    {"codec", "--codec"},
    {"format", "--format"},
    {"padding", "--padding"},        // dataset render
    {"iterations", "--iterations"},  // dataset render
    {"instances", "--instances"},    // dataset render
    {"rate", "--rate"},              // dataset search
    {"points", "--points"},          // dataset search
};

// Named inside messages, not as their subject.
constexpr std::pair<std::string_view, std::string_view> kInside[] = {
    {"allow_expansive accepts it", "--allow-expansive accepts it"},
    {"(raise max_seconds)", "(raise --max-seconds)"},
    {"(try invert or threshold)", "(try --invert or --threshold)"},
    {"try a larger size)", "try a larger --size)"},
    {"; skip_gaps goes on without", "; --skip-gaps goes on without"},
    {"(pick one with codec)", "(pick one with --codec)"},
    {"(timing keep); use .mkv or .mp4, or timing constant",
     "(--fps-mode vfr); use .mkv or .mp4, or --fps-mode cfr"},
};

}  // namespace

std::string with_flag_names(const std::string& message) {
  std::string out = message;
  for (const auto& [parameter, flag] : kFlags)
    if (out.size() > parameter.size() && out.compare(0, parameter.size(), parameter) == 0 &&
        out[parameter.size()] == ':') {
      out.replace(0, parameter.size(), flag);
      break;
    }
  for (const auto& [phrase, replacement] : kInside)
    if (const auto at = out.find(phrase); at != std::string::npos)
      out.replace(at, phrase.size(), replacement);
  return out;
}

}  // namespace ifsfx::app
