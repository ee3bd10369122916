// SPDX-License-Identifier: Apache-2.0
// `ifsfx apply MAP IMAGE -o OUT`: colours an image through a saved steal map (from
// `ifsfx render ... --mode steal --save-map MAP`), one remap.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/stop_signals.h"
#include "ifs/image_io.h"
#include "ifs/steal_map.h"
#include "ifs/steal_picture.h"
#include "run/picture_options.h"

namespace ifsfx::app {
namespace {

struct ApplyArgs {
  std::string map;
  std::string image;
  std::string output;
  bool nearest = false;
  std::string background = "black";
  int threads = 0;
  int bits = 8;
};

void run_apply(const ApplyArgs& args) {
  const Rgb background = colour_option(args.background);
  StopSignals signals;
  WriteOptions write;
  write.bits = args.bits;
  write.output.cancel = StopSignals::token();
  write.output.inputs.add(args.map);
  write.output.inputs.add(args.image);
  check_writable_image(args.output, write.output, write.bits);
  const StealMap map = load_steal_map(args.map);
  const cv::Mat source = read_image(args.image).pixels;
  ApplyOptions options;
  options.interpolation = args.nearest ? Interpolation::nearest : Interpolation::bilinear;
  options.background = background_scalar(background, source.depth());
  options.threads = args.threads;
  const cv::Mat out =
      with_coverage_alpha(apply(map, source, options), map.coverage, format_has_alpha(args.output));
  write_image(args.output, out, write);
}

}  // namespace

void add_apply_command(CLI::App& app) {
  auto args = std::make_shared<ApplyArgs>();
  auto* cmd = app.add_subcommand(
      "apply", "Colour an image through a steal map saved by `ifsfx render --save-map`");
  cmd->add_option("map", args->map, "Steal map file")->required();
  cmd->add_option("image", args->image, "Source image (any format OpenImageIO reads)")->required();
  cmd->add_option("-o,--output", args->output, "Output image, the map's size; format by extension")
      ->required();
  cmd->add_flag("--nearest", args->nearest,
                "Nearest source pixel instead of bilinear interpolation");
  cmd->add_option("--background", args->background,
                  "Colour off the attractor in formats without alpha (black, white, #rrggbb, "
                  "R,G,B); PNG/TIFF/EXR get a transparent background")
      ->capture_default_str();
  add_threads_option(*cmd, args->threads);
  cmd->add_option("--bits", args->bits, "Bits per channel of PNG/TIFF output: 8 or 16")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16}));
  cmd->callback([args] { run_apply(*args); });
}

}  // namespace ifsfx::app
