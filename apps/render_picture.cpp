// SPDX-License-Identifier: Apache-2.0
#include "apps/render_picture.h"

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {

const char* to_string(RenderMode mode) noexcept {
  switch (mode) {
    case RenderMode::attractor:
      return "attractor";
    case RenderMode::measure:
      return "measure";
    case RenderMode::tops:
      return "tops";
    case RenderMode::steal:
      return "steal";
  }
  return "measure";
}

RenderMode parse_render_mode(const std::string& text, const std::string& what) {
  for (RenderMode mode :
       {RenderMode::attractor, RenderMode::measure, RenderMode::tops, RenderMode::steal})
    if (text == to_string(mode)) return mode;
  throw Error(ErrorKind::invalid_argument,
              fmt::format("{}: attractor, measure, tops or steal (got {})", what, text));
}

cv::Mat render_picture(const Ifs& F, cv::Size size, const RenderOptions& options,
                       const PictureArgs& args, const std::string& output,
                       std::vector<OutputFile>& staged, RenderStats* stats) {
  switch (args.mode) {
    case RenderMode::attractor:
      return render_attractor(F, size, options, stats);
    case RenderMode::measure:
      return render_measure(F, size, options, stats);
    case RenderMode::tops:
      return tops_image(F, size, options, args.steal.exact, args.second_symbol,
                        args.steal.background, output, stats);
    case RenderMode::steal:
      return steal_image(F, size, options, args.steal, output, staged, stats);
  }
  return {};
}

}  // namespace ifsfx::app
