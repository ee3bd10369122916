// Option parsing shared by the subcommands: sizes, views, colours, thread counts. Thin wrappers
// that turn a command-line string into a library type, reporting errors as ifsfx::Error.
#pragma once

#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/view.h"

namespace ifsfx::app {

// "WxH", checked (1..32768 a side).
inline cv::Size size_option(const std::string& text, const std::string& what = "--size") {
  return parse_size(text, what);
}

// "x0,y0,x1,y1", or nothing for an empty string (auto-framing).
inline std::optional<Box> view_option(const std::string& text, const std::string& what = "--view") {
  if (text.empty()) return std::nullopt;
  return parse_box(text, what);
}

}  // namespace ifsfx::app
