// SPDX-License-Identifier: Apache-2.0
// Renders one flame with ifsfx's flame renderer (flame/render.h), for the comparisons with
// flam3-render (bench/flame_vs_flam3.py) until `ifsfx render FILE.flame` exists:
//   flame_render FILE.flame[:NAME|:INDEX] -o out.png [--size WxH] [--quality Q] [--seed N]
//                [--threads N] [--double-lanes]
// Prints the points, re-seeded points, seconds and coverage on stdout.
#include <cstdio>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "flame/flame_file.h"
#include "flame/render.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/view.h"

int main(int argc, char** argv) {
  using namespace ifsfx;
  std::string spec, out;
  flame::FlameRenderOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string_view a = argv[i];
      const auto value = [&]() -> std::string {
        if (i + 1 >= argc)
          throw Error(ErrorKind::invalid_argument, fmt::format("{} needs a value", a));
        return argv[++i];
      };
      if (a == "-o")
        out = value();
      else if (a == "--size")
        options.size = parse_size(value());
      else if (a == "--quality")
        options.quality = std::stod(value());
      else if (a == "--seed")
        options.seed = std::stoull(value());
      else if (a == "--threads")
        options.threads = std::stoi(value());
      else if (a == "--double-lanes")
        options.float_lanes = false;
      else if (spec.empty())
        spec = a;
      else
        throw Error(ErrorKind::invalid_argument, fmt::format("unexpected argument {}", a));
    }
    if (spec.empty() || out.empty())
      throw Error(ErrorKind::invalid_argument,
                  "usage: flame_render FILE.flame[:NAME] -o out.png [--size WxH] [--quality Q] "
                  "[--seed N] [--threads N] [--double-lanes]");
    const flame::Flame f = flame::read_flame(spec);
    flame::FlameRenderStats stats;
    const cv::Mat image = flame::render_flame(f, options, &stats);
    write_image(out, image);
    fmt::print("points {} reseeded {} seconds {:.3f} coverage {:.4f}\n", stats.points,
               stats.reseeded, stats.seconds, stats.coverage);
  } catch (const std::exception& e) {
    fmt::print(stderr, "flame_render: {}\n", e.what());
    return 2;
  }
  return 0;
}
