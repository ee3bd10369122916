// SPDX-License-Identifier: Apache-2.0
#include "apps/steal_modes.h"

#include "apps/cli_options.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"

namespace ifsfx::app {

Rgb colour_option(const std::string& text, const std::string& what) {
  std::string t = text;
  for (auto& ch : t) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t == "black") return {0, 0, 0};
  if (t == "white") return {1, 1, 1};
  const auto fail = [&] {
    return Error(
        ErrorKind::parse,
        fmt::format("{}: a colour is black, white, #rrggbb or R,G,B with 0..255 (got '{}')", what,
                    text));
  };
  if (t.size() == 7 && t[0] == '#') {
    int v[3];
    for (int i = 0; i < 3; ++i) {
      std::size_t used = 0;
      try {
        v[i] = std::stoi(t.substr(1 + 2 * static_cast<std::size_t>(i), 2), &used, 16);
      } catch (const std::exception&) {
        throw fail();
      }
      if (used != 2) throw fail();
    }
    return {v[0] / 255.0, v[1] / 255.0, v[2] / 255.0};
  }
  int r = 0, g = 0, b = 0;
  char tail = 0;
  if (std::sscanf(t.c_str(), "%d,%d,%d%c", &r, &g, &b, &tail) == 3 && r >= 0 && r <= 255 &&
      g >= 0 && g <= 255 && b >= 0 && b <= 255)
    return {r / 255.0, g / 255.0, b / 255.0};
  throw fail();
}

bool format_has_alpha(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr";
}

cv::Mat tops_image(const Ifs& F, cv::Size size, const TopsOptions& options, const Rgb& background,
                   const std::string& output, RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  TopsPictureStats tops;
  cv::Mat image = tops_picture(F, size, options, background, format_has_alpha(output), &tops);
  if (stats)
    *stats = {
        .points = tops.points,
        .seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        .coverage = tops.coverage,
        .view = tops.view};
  return image;
}

cv::Mat steal_image(const Ifs& F, cv::Size size, const StealMapOptions& options,
                    const StealModeArgs& args, const std::string& output,
                    std::vector<OutputFile>& staged, RenderStats* stats) {
  if (args.source.empty())
    throw Error(ErrorKind::invalid_argument, "--source: --mode steal needs a source image");
  // Read first: a missing or unreadable source fails before any long work.
  const cv::Mat source = read_image(args.source).pixels;
  const Ifs G = colouring_option(args.colouring, F);
  StealMapStats ss;
  const StealMap map = compute_steal_map(F, G, size, options, &ss);
  if (!args.save_map.empty()) {
    OutputFile file(args.save_map, args.output);
    save(map, file);
    staged.push_back(std::move(file));
  }
  const cv::Mat coloured = apply(map, source,
                                 {.background = background_scalar(args.background, source.depth()),
                                  .threads = options.sampling.threads});
  if (!args.quiet)
    fmt::print("steal map{}: {} levels; {:.2f}% of pixels on the attractor{}\n",
               options.exact ? " (exact)" : " (chaos game)", ss.levels, 100 * ss.coverage,
               options.exact ? std::string()
                             : fmt::format(" ({:.2f}% hit by points, {} reached by "
                                           "Hutchinson passes, {} filled from "
                                           "neighbours, {} rounds)",
                                           100 * ss.hit, ss.propagated, ss.filled, ss.rounds));
  if (stats) {
    stats->points = ss.points;
    stats->seconds = ss.seconds;
    stats->coverage = ss.coverage;
    stats->view = ss.view;
  }
  return with_coverage_alpha(coloured, map.coverage, format_has_alpha(output));
}

}  // namespace ifsfx::app
