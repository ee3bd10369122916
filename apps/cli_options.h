// Option parsing shared by the subcommands: sizes, views, colours, thread counts. Thin wrappers
// that turn a command-line string into a library type, reporting errors as ifsfx::Error.
#pragma once

#include <cctype>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/view.h"

namespace ifsfx::app {

// The --help text of an option taking one of `names`, e.g. "{attractor,measure}=measure" (CLI11's
// own shows the enum's numbers too).
template <class Map>
std::string choices_text(const Map& names, const std::string& fallback) {
  std::string text = "{";
  for (const auto& [name, value] : names) text += (text.size() > 1 ? "," : "") + name;
  return text + "}=" + fallback;
}

// A transform for an enum option taking one of `names` (case ignored), with a plain error:
// "--mode: must be one of attractor, measure, steal, tops (got 'bogus')".
template <class Map>
CLI::Validator choice(const Map& names) {
  return CLI::Validator(
      [names](std::string& value) -> std::string {
        std::string key = value;
        for (auto& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        const auto found = names.find(key);
        if (found == names.end()) {
          std::string list;
          for (const auto& [name, unused] : names) list += (list.empty() ? "" : ", ") + name;
          return "must be one of " + list + " (got '" + value + "')";
        }
        value = std::to_string(static_cast<int>(found->second));  // CLI11 reads enums as numbers
        return {};
      },
      "");
}

// "WxH", checked (1..32768 a side).
inline cv::Size size_option(const std::string& text, const std::string& what = "--size") {
  return parse_size(text, what);
}

// "x0,y0,x1,y1", or nothing for an empty string (auto-framing).
inline std::optional<Box> view_option(const std::string& text, const std::string& what = "--view") {
  if (text.empty()) return std::nullopt;
  return parse_box(text, what);
}

// The colouring IFS G for a drawing IFS F (the --colouring option): see load_colouring.
inline Ifs colouring_option(const std::string& spec, const Ifs& F,
                            const std::string& what = "--colouring") {
  return load_colouring(spec, F, what);
}

}  // namespace ifsfx::app
