// SPDX-License-Identifier: Apache-2.0
// `ifsfx render PRESET -o OUT`: an IFS rendered to a still image by the chaos game.
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/commands.h"
#include "apps/render_metadata.h"
#include "apps/steal_modes.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/render.h"

namespace ifsfx::app {
namespace {

enum class Mode { attractor, measure, tops, steal };

struct RenderArgs {
  std::string preset;
  std::string output;
  std::string size = "1024x1024";
  Mode mode = Mode::measure;
  std::string view;
  RenderOptions options;  // the options bind here; view and cancel are set by run_render
  int bits = 8;
  bool smallest = false;
  bool allow_expansive = false;
  bool quiet = false;
  // tops and steal modes (apps/steal_modes.h)
  std::string source;
  std::string colouring;
  bool exact = true;              // --exact (default) or --chaos
  bool map_method_given = false;  // either was on the command line
  bool second_symbol = false;
  std::string save_map;
  std::string background;
};

const char* mode_name(Mode mode) {
  switch (mode) {
    case Mode::attractor:
      return "attractor";
    case Mode::measure:
      return "measure";
    case Mode::tops:
      return "tops";
    case Mode::steal:
      return "steal";
  }
  return "measure";
}

// The tops/steal options are refused in the modes that would ignore them.
void check_mode_options(const RenderArgs& args) {
  const auto refuse = [&](bool given, const char* option, const char* modes) {
    if (given)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: only with --mode {} (got --mode {})", option, modes,
                              mode_name(args.mode)));
  };
  const bool tops = args.mode == Mode::tops, steal = args.mode == Mode::steal;
  refuse(!steal && !args.source.empty(), "--source", "steal");
  refuse(!steal && !args.colouring.empty(), "--colouring", "steal");
  refuse(!steal && !args.save_map.empty(), "--save-map", "steal");
  refuse(!tops && args.second_symbol, "--second-symbol", "tops");
  refuse(!tops && !steal && args.map_method_given, "--exact/--chaos", "tops or steal");
  refuse(!tops && !steal && !args.background.empty(), "--background", "tops or steal");
  if (steal && args.source.empty())
    throw Error(ErrorKind::invalid_argument, "--source: --mode steal needs a source image");
}

// The output policy: no output replaces an input, the two outputs differ, and both are checked
// before the long work.
OutputOptions checked_outputs(const RenderArgs& args) {
  OutputOptions output{.cancel = StopSignals::token()};
  add_preset_input(output.inputs, args.preset);
  add_preset_input(output.inputs, args.colouring);
  output.inputs.add(args.source);
  check_writable_image(args.output, output, args.bits);
  if (!args.save_map.empty()) {
    check_output(args.save_map, output);
    if (same_output(args.save_map, args.output))
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("--save-map {}: must differ from -o (got the same file)", args.save_map));
  }
  return output;
}

// The picture in the chosen mode; the steal mode's saved map joins `staged`.
cv::Mat render_picture(const Ifs& ifs, cv::Size size, const RenderArgs& args,
                       const RenderOptions& options, const OutputOptions& output,
                       std::vector<OutputFile>& staged, RenderStats& stats) {
  const Rgb background = colour_option(args.background.empty() ? "black" : args.background);
  switch (args.mode) {
    case Mode::attractor:
      return render_attractor(ifs, size, options, &stats);
    case Mode::measure:
      return render_measure(ifs, size, options, &stats);
    case Mode::tops:
      return tops_image(
          ifs, size,
          {.sampling = options.sampling, .exact = args.exact, .second_symbol = args.second_symbol},
          background, args.output, &stats);
    case Mode::steal:
      return steal_image(ifs, size, {.sampling = options.sampling, .exact = args.exact},
                         {.source = args.source,
                          .colouring = args.colouring,
                          .save_map = args.save_map,
                          .background = background,
                          .quiet = args.quiet,
                          .output = output},
                         args.output, staged, &stats);
  }
  return {};
}

void print_summary(const std::string& name, cv::Size size, const RenderArgs& args,
                   const RenderStats& stats) {
  // The exact modes plot no chaos-game points: say so rather than print a rate of zero.
  const std::string work =
      stats.points > 0
          ? fmt::format("{:.1f} M points in {:.3f} s ({:.0f} Mpts/s)", stats.points / 1e6,
                        stats.seconds, stats.points / 1e6 / std::max(stats.seconds, 1e-9))
          : fmt::format("{} in {:.3f} s", args.exact ? "exact descent" : "rendered", stats.seconds);
  fmt::print("{} ({}, {}x{}): {}, coverage {:.1f}% -> {}\n", name, mode_name(args.mode), size.width,
             size.height, work, 100 * stats.coverage, args.output);
}

void run_render(const RenderArgs& args) {
  const cv::Size size = size_option(args.size);
  check_mode_options(args);
  StopSignals signals;
  const OutputOptions output = checked_outputs(args);
  const IfsPreset preset = load_preset(args.preset, {.allow_expansive = args.allow_expansive});
  RenderOptions options = args.options;
  options.sampling.view = view_option(args.view);
  options.sampling.cancel = output.cancel;

  RenderStats stats;
  std::vector<OutputFile> staged;  // put in place together at the end (the image, the map)
  const cv::Mat image = render_picture(preset.ifs, size, args, options, output, staged, stats);
  OutputFile image_file(args.output, output);
  write_image(image_file, image,
              {.bits = args.bits,
               .smallest = args.smallest,
               .metadata = render_metadata(preset, mode_name(args.mode), options.sampling.seed,
                                           stats.view)});
  staged.push_back(std::move(image_file));
  commit_together(staged);
  if (!args.quiet) print_summary(preset.ifs.name, size, args, stats);
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Render an IFS preset to a still image");
  cmd->add_option(
         "preset", args->preset,
         "Preset: a shipped name (see `ifsfx presets`), a .toml/.ifs path, or FILE.ifs:NAME")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output image; format by extension: .png (8/16-bit), .tif, .exr (float), .jpg")
      ->required();
  cmd->add_option("--size", args->size, "Output size WxH in pixels")->capture_default_str();
  const std::map<std::string, Mode> modes{{"attractor", Mode::attractor},
                                          {"measure", Mode::measure},
                                          {"tops", Mode::tops},
                                          {"steal", Mode::steal}};
  cmd->add_option("--mode", args->mode,
                  "attractor: the set; measure: log-density of the invariant measure, "
                  "coloured by map; tops: each pixel coloured by the first symbol of its top "
                  "address; steal: colours stolen from --source (fractal tops, colour stealing)")
      ->transform(choice(modes))
      ->default_str("measure")
      ->option_text(choices_text(modes, "measure"));
  cmd->add_option("--view", args->view,
                  "Plane rectangle x0,y0,x1,y1 shown (default: the attractor, auto-framed)");
  cmd->add_option("--margin", args->options.sampling.margin,
                  "Auto-framing margin, fraction of the larger side")
      ->capture_default_str()
      ->check(number_in(0, kMaxMargin));
  cmd->add_option("--quality", args->options.sampling.quality, "Chaos-game points per output pixel")
      ->capture_default_str()
      ->check(number_in(0, kMaxQuality, true));
  cmd->add_option("--supersample", args->options.supersample,
                  "Render at K times the size and box-filter down (measure mode)")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  cmd->add_option("--gamma", args->options.gamma, "Display gamma of the tone map (measure mode)")
      ->capture_default_str()
      ->check(number_in(0, 100, true));
  cmd->add_option("--brightness", args->options.brightness,
                  "k of the log-density tone map, relative to the mean density (measure mode)")
      ->capture_default_str()
      ->check(number_in(0, 1e6, true));
  cmd->add_option("--seed", args->options.sampling.seed,
                  "Random seed: the same seed gives the same image")
      ->capture_default_str()
      ->check(not_negative());
  add_threads_option(*cmd, args->options.sampling.threads);
  cmd->add_option("--bits", args->bits, "Bits per channel of PNG/TIFF output: 8 or 16")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16}));
  cmd->add_flag("--smallest", args->smallest,
                "PNG output: the smallest file (zlib level 9, filter chosen per row) instead "
                "of the fastest to write (level 1, sub filter)");
  cmd->add_flag("--allow-expansive", args->allow_expansive,
                "Accept maps with factor >= 1 when the IFS contracts on average");
  cmd->add_flag("-q,--quiet", args->quiet, "Do not print the summary line");
  cmd->add_option("--source", args->source,
                  "steal mode: image to steal colours from (any format OpenImageIO reads)");
  cmd->add_option("--colouring", args->colouring,
                  "steal mode: colouring IFS preset with as many maps, fitted to the source "
                  "(default: a tiling of the source for the number of maps)");
  // The exact descent is the default: faster than the chaos game for every shipped preset at
  // 720p and 1080p, and without noise (bench/README.md, steal_modes_bench).
  auto* map_method = cmd->add_flag(
      "--exact,!--chaos", args->exact,
      "tops/steal modes: top addresses by exact per-pixel descent (default; no noise or holes), "
      "or with --chaos by the chaos game, the paper's method (--quality points per pixel)");
  cmd->add_flag("--second-symbol", args->second_symbol,
                "tops mode: mix in the colour of the second symbol of the top address");
  cmd->add_option("--save-map", args->save_map,
                  "steal mode: also save the steal map, for `ifsfx apply MAP IMAGE`");
  cmd->add_option("--background", args->background,
                  "tops/steal modes: colour off the attractor in formats without alpha "
                  "(black, white, #rrggbb, R,G,B); PNG/TIFF/EXR get a transparent background")
      ->default_str("black");
  cmd->callback([args, map_method] {
    args->map_method_given = map_method->count() > 0;
    run_render(*args);
  });
}

}  // namespace ifsfx::app
