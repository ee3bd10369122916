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
#include "apps/seamless_options.h"
#include "apps/steal_modes.h"
#include "apps/stop_signals.h"
#include "flame/flame_write.h"
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
  std::string save_flame;  // --save-flame: the preset as a flame file (docs/flames.md)
  std::string background;
  // --seamless, --tiles, --tile-offset (apps/seamless_options.h)
  SeamlessArgs tiles;
  bool margin_given = false;  // --margin was on the command line
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
  if (!args.save_flame.empty()) {
    check_output(args.save_flame, output);
    if (same_output(args.save_flame, args.output) ||
        (!args.save_map.empty() && same_output(args.save_flame, args.save_map)))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("--save-flame {}: must differ from the other outputs (got the same "
                              "file)",
                              args.save_flame));
  }
  return output;
}

// The picture in the chosen mode; the steal mode's saved map joins `staged`. With --seamless the
// modes render one period, laid out as --tiles and --tile-offset say (steal mode lays out its
// map, so that --save-map colours the whole picture too).
cv::Mat render_picture(const Ifs& ifs, cv::Size size, const RenderArgs& args,
                       const RenderOptions& options, const TileLayout& layout,
                       const OutputOptions& output, std::vector<OutputFile>& staged,
                       RenderStats& stats) {
  const Rgb background = colour_option(args.background.empty() ? "black" : args.background);
  switch (args.mode) {
    case Mode::attractor:
      return laid_out(render_attractor(ifs, size, options, &stats), layout);
    case Mode::measure:
      return laid_out(render_measure(ifs, size, options, &stats), layout);
    case Mode::tops:
      return laid_out(tops_image(ifs, size,
                                 {.sampling = options.sampling,
                                  .exact = args.exact,
                                  .second_symbol = args.second_symbol},
                                 background, args.output, &stats),
                      layout);
    case Mode::steal:
      return steal_image(ifs, size, {.sampling = options.sampling, .exact = args.exact},
                         {.source = args.source,
                          .colouring = args.colouring,
                          .save_map = args.save_map,
                          .background = background,
                          .quiet = args.quiet,
                          .output = output,
                          .layout = layout},
                         args.output, staged, &stats);
  }
  return {};
}

// `size`: the picture's (the tile's times --tiles with --seamless).
void print_summary(const std::string& name, cv::Size size, const RenderArgs& args,
                   const RenderStats& stats) {
  // The exact modes plot no chaos-game points: say so rather than print a rate of zero.
  const std::string work =
      stats.points > 0
          ? fmt::format("{:.1f} M points in {:.3f} s ({:.0f} Mpts/s)", stats.points / 1e6,
                        stats.seconds, stats.points / 1e6 / std::max(stats.seconds, 1e-9))
          : fmt::format("{} in {:.3f} s", args.exact ? "exact descent" : "rendered", stats.seconds);
  fmt::print("{} ({}{}, {}x{}): {}, coverage {:.1f}% -> {}\n", name, mode_name(args.mode),
             args.tiles.seamless ? ", seamless" : "", size.width, size.height, work,
             100 * stats.coverage, args.output);
}

void run_render(const RenderArgs& args) {
  const cv::Size size = size_option(args.size);
  check_mode_options(args);
  StopSignals signals;
  const OutputOptions output = checked_outputs(args);
  const IfsPreset preset = load_preset(args.preset, {.allow_expansive = args.allow_expansive});
  const TileLayout layout = tile_layout(args.tiles, preset.seamless, size);
  RenderOptions options = args.options;
  options.sampling.view = view_option(args.view);
  options.sampling.cancel = output.cancel;
  options.sampling.seamless = args.tiles.seamless;
  if (options.sampling.seamless) {
    // The tile: --view, the preset's own, or the attractor framed with no margin (a margin would
    // put empty bands between the periods).
    if (!options.sampling.view && preset.seamless) options.sampling.view = preset.seamless->view;
    if (!args.margin_given) options.sampling.margin = 0;
  }

  RenderStats stats;
  std::vector<OutputFile> staged;  // put in place together at the end (the image, the map)
  const cv::Mat image =
      render_picture(preset.ifs, size, args, options, layout, output, staged, stats);
  auto metadata = render_metadata(preset, mode_name(args.mode), options.sampling.seed, stats.view);
  if (options.sampling.seamless)
    for (auto& entry : seamless_metadata(stats.view, layout)) metadata.push_back(entry);
  OutputFile image_file(args.output, output);
  write_image(image_file, image,
              {.bits = args.bits, .smallest = args.smallest, .metadata = std::move(metadata)});
  staged.push_back(std::move(image_file));
  if (!args.save_flame.empty()) {
    // The same maps, framing and tone as this render's measure, as flam3 and its kin read them.
    OutputFile flame_file(args.save_flame, output);
    write_file(flame_file,
               flame::flame_xml(flame::flame_from_ifs(preset.ifs, {.size = size,
                                                                   .sampling = options.sampling,
                                                                   .brightness = options.brightness,
                                                                   .gamma = options.gamma})));
    staged.push_back(std::move(flame_file));
  }
  commit_together(staged);
  if (!args.quiet) print_summary(preset.ifs.name, image.size(), args, stats);
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
  auto* margin = cmd->add_option("--margin", args->options.sampling.margin,
                                 "Auto-framing margin, fraction of the larger side (0 with "
                                 "--seamless)")
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
  cmd->add_option("--save-flame", args->save_flame,
                  "Also save the preset as a flame file (.flame) that flam3, Apophysis and "
                  "Fractorium open, framed and toned as this render's measure");
  cmd->add_option("--background", args->background,
                  "tops/steal modes: colour off the attractor in formats without alpha "
                  "(black, white, #rrggbb, R,G,B); PNG/TIFF/EXR get a transparent background")
      ->default_str("black");
  add_seamless_options(*cmd, args->tiles);
  cmd->callback([args, map_method, margin] {
    args->map_method_given = map_method->count() > 0;
    args->margin_given = margin->count() > 0;
    run_render(*args);
  });
}

}  // namespace ifsfx::app
