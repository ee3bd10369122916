// SPDX-License-Identifier: Apache-2.0
// Arguments as the jobs take them from any door: sizes "WxH", views "x0,y0,x1,y1", presets and
// colouring IFSs by name, and the input files a job's outputs must never replace. Messages name
// the argument as the caller spells it (`what`: "--size" for the command line, "size" for Python).
#pragma once

#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/view.h"

namespace ifsfx::app {

// A preset's files as inputs no output may replace: the spec itself and, for FILE:ENTRY, FILE.
inline void add_preset_input(InputFiles& inputs, const std::string& spec) {
  if (spec.empty()) return;
  inputs.add(spec);
  if (const auto colon = spec.rfind(':'); colon != std::string::npos)
    inputs.add(spec.substr(0, colon));
}

inline cv::Size size_option(const std::string& text, const std::string& what = "--size") {
  return parse_size(text, what);
}

// The view, or nothing for an empty text (auto-framed).
inline std::optional<Box> view_option(const std::string& text, const std::string& what = "--view") {
  if (text.empty()) return std::nullopt;
  return parse_box(text, what);
}

inline Ifs colouring_option(const std::string& spec, const Ifs& F,
                            const std::string& what = "--colouring") {
  return load_colouring(spec, F, what);
}

}  // namespace ifsfx::app
