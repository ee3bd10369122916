// SPDX-License-Identifier: Apache-2.0
// `ifsfx render PRESET -o OUT`: an IFS rendered to a still image by the chaos game.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/option_groups.h"
#include "cli/stop_signals.h"
#include "flame/flame_file.h"
#include "flame/flame_write.h"
#include "flame/render.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "run/picture_options.h"
#include "run/render_metadata.h"
#include "run/render_modes.h"
#include "run/render_still.h"
#include "run/seamless_options.h"

namespace ifsfx::app {
namespace {

struct RenderArgs {
  std::string preset;
  std::string output;
  std::string size = "1024x1024";
  RenderMode mode = RenderMode::measure;
  std::string view;
  RenderOptions options;  // the options bind here; view and cancel are set by run_render
  int bits = 8;
  bool smallest = false;
  bool allow_expansive = false;
  bool quiet = false;
  // tops and steal modes (run/picture_options.h)
  std::string source;
  std::string colouring;
  bool exact = true;              // --exact (default) or --chaos
  bool map_method_given = false;  // either was on the command line
  bool second_symbol = false;
  std::string save_map;
  std::string save_flame;  // also write the IFS as a flame file (flame/flame_write.h)
  std::string background;
  // --seamless, --tiles, --tile-offset (run/seamless_options.h)
  SeamlessArgs tiles;
  bool margin_given = false;  // --margin was on the command line
  // The flags given on the command line that a flame takes from its file instead (a flame's
  // size and quality are its own unless given).
  std::vector<std::string> given;
  bool was_given(const std::string& flag) const {
    return std::find(given.begin(), given.end(), flag) != given.end();
  }
};

// The tops/steal options are refused in the modes that would ignore them (run/render_modes.h);
// `background_taken`: --background is checked by the caller (a flame's measure takes one).
void check_mode_options(const RenderArgs& args, bool background_taken = false) {
  app::check_mode_options(
      args.mode,
      {.source = {"--source", !args.source.empty()},
       .colouring = {"--colouring", !args.colouring.empty()},
       .save_map = {"--save-map", !args.save_map.empty()},
       .second_symbol = {"--second-symbol", args.second_symbol},
       .map_method = {"--exact/--chaos", args.map_method_given},
       .background = {"--background", !background_taken && !args.background.empty()}},
      "--mode");
}

// The output policy: no output replaces an input, the two outputs differ, and both are checked
// before the long work.
OutputOptions checked_outputs(const RenderArgs& args) {
  OutputOptions output{.cancel = StopSignals::token()};
  add_preset_input(output.inputs, args.preset);
  add_preset_input(output.inputs, args.colouring);
  output.inputs.add(args.source);
  check_writable_image(args.output, output, args.bits);
  for (const auto& [flag, path] :
       {std::pair{"--save-map", &args.save_map}, std::pair{"--save-flame", &args.save_flame}}) {
    if (path->empty()) continue;
    check_output(*path, output);
    if (same_output(*path, args.output))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{} {}: must differ from -o (got the same file)", flag, *path));
  }
  if (!args.save_map.empty() && !args.save_flame.empty() &&
      same_output(args.save_map, args.save_flame))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--save-flame {}: must differ from --save-map (got the same file)",
                            args.save_flame));
  return output;
}

// The steal map's figures (the coverage policy's, for the chaos game).
void print_steal_summary(const StealMapStats& ss, bool exact) {
  fmt::print("steal map{}: {} levels; {:.2f}% of pixels on the attractor{}\n",
             exact ? " (exact)" : " (chaos game)", ss.levels, 100 * ss.coverage,
             exact ? std::string()
                   : fmt::format(" ({:.2f}% hit by points, {} reached by Hutchinson passes, {} "
                                 "filled from neighbours, {} rounds)",
                                 100 * ss.hit, ss.propagated, ss.filled, ss.rounds));
}

// The picture in the chosen mode (run/render_still.h); the steal mode's map, with --save-map,
// joins `staged`, to be put in place with the image (commit_together). With --seamless the modes
// render one period, laid out as --tiles and --tile-offset say (the steal mode lays out its map,
// so that --save-map colours the whole picture too).
StillResult render_picture(const engine::Drawing& F, cv::Size size, const RenderArgs& args,
                           const RenderOptions& options, const TileLayout& layout,
                           const OutputOptions& output, std::vector<OutputFile>& staged) {
  StillJob job{.mode = args.mode,
               .size = size,
               .options = options,
               .exact = args.exact,
               .second_symbol = args.second_symbol,
               .background = colour_option(args.background.empty() ? "black" : args.background),
               .alpha = format_has_alpha(args.output),
               .layout = layout};
  if (render_mode_info(args.mode).source) {
    // Read first: a missing or unreadable source fails before any long work.
    job.source = read_image(args.source).pixels;
    job.colouring = engine::colouring_for(args.colouring, F, "--colouring");
  }
  StillResult still = render_still(F, job);
  if (still.map && !args.save_map.empty()) {
    OutputFile file(args.save_map, output);
    save(*still.map, file);
    staged.push_back(std::move(file));
  }
  if (still.map && !args.quiet) print_steal_summary(still.steal, args.exact);
  return still;
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
  fmt::print("{} ({}{}, {}x{}): {}, coverage {:.1f}% -> {}\n", name, to_string(args.mode),
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

  std::vector<OutputFile> staged;  // put in place together at the end (the image, the map)
  const StillResult still = render_picture(preset.ifs, size, args, options, layout, output, staged);
  if (!args.save_flame.empty()) {
    // The IFS as a flame drawing this measure, framed as this picture (flame_from_ifs).
    OutputFile file(args.save_flame, output);
    write_file(file,
               flame::flame_xml(flame::flame_from_ifs(preset.ifs, {.size = size,
                                                                   .sampling = options.sampling,
                                                                   .brightness = options.brightness,
                                                                   .gamma = options.gamma})));
    staged.push_back(std::move(file));
  }
  const cv::Mat& image = still.image;
  const RenderStats& stats = still.stats;
  auto metadata = render_metadata(preset, to_string(args.mode), options.sampling.seed, stats.view);
  if (options.sampling.seamless)
    for (auto& entry : seamless_metadata(stats.view, layout)) metadata.push_back(entry);
  OutputFile image_file(args.output, output);
  write_image(image_file, image,
              {.bits = args.bits, .smallest = args.smallest, .metadata = std::move(metadata)});
  staged.push_back(std::move(image_file));
  commit_together(staged);
  if (!args.quiet) print_summary(preset.ifs.name, image.size(), args, stats);
}

// What a flame file brings itself (its camera, its tone mapping) is not taken from a flag: a given
// one is refused, naming the flame.
void refuse_flame_flags(const RenderArgs& args, std::initializer_list<const char*> flags) {
  for (const char* flag : flags)
    if (args.was_given(flag))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: a flame brings its own (got {})", flag, args.preset));
}

// `ifsfx render FILE.flame[:NAME] -o OUT`: the flame as flam3 renders it (flame/render.h), at
// its own size and quality unless --size and --quality are given.
void run_flame_render(const RenderArgs& args) {
  check_flame_mode(args.mode, "--mode");
  check_mode_options(args, true);
  refuse_flame_flags(args, {"--view", "--margin", "--supersample", "--gamma", "--brightness",
                            "--seamless", "--tiles", "--tile-offset", "--allow-expansive"});
  std::optional<flame::Rgba> background;  // --background: in place of the file's
  if (!args.background.empty()) {
    background = flame_background_option(args.background);
    if (background->a == 0 && !format_has_alpha(args.output))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("--background transparent: needs an output that keeps alpha (.png, "
                              ".tif, .tiff, .exr; got {})",
                              args.output));
  }
  StopSignals signals;
  const OutputOptions output = checked_outputs(args);
  flame::Flame f = flame::read_flame(args.preset);
  if (background) f.tone.background = *background;
  flame::FlameRenderOptions options{.seed = args.options.sampling.seed,
                                    .threads = args.options.sampling.threads,
                                    .cancel = output.cancel,
                                    .channels = format_has_alpha(args.output) ? 4 : 3};
  if (args.was_given("--size")) options.size = size_option(args.size);
  if (args.was_given("--quality")) options.quality = args.options.sampling.quality;
  std::string ext = std::filesystem::path(args.output).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  options.depth = ext == ".exr" ? CV_32F : args.bits == 16 ? CV_16U : CV_8U;
  flame::FlameRenderStats stats;
  const cv::Mat image = flame::render_flame(f, options, &stats);
  std::vector<OutputFile> staged;
  if (!args.save_flame.empty()) {
    OutputFile file(args.save_flame, output);
    write_file(file, flame::flame_xml(f));
    staged.push_back(std::move(file));
  }
  OutputFile image_file(args.output, output);
  write_image(image_file, image,
              {.bits = args.bits,
               .smallest = args.smallest,
               .metadata = flame_render_metadata(args.preset, "measure", options.seed)});
  staged.push_back(std::move(image_file));
  commit_together(staged);
  if (!args.quiet)
    fmt::print(
        "{} (flame, {}x{}): {:.1f} M points in {:.3f} s ({:.0f} Mpts/s), coverage {:.1f}% -> "
        "{}\n",
        f.name.empty() ? args.preset : f.name, image.cols, image.rows, stats.points / 1e6,
        stats.seconds, stats.points / 1e6 / std::max(stats.seconds, 1e-9), 100 * stats.coverage,
        args.output);
}

// `ifsfx render FILE.flame[:NAME] --mode attractor|tops|steal -o OUT`: the flame's xforms through
// the chaos game (flame/flame_chaos.h), framed by its camera, at its own size unless --size is
// given; --chaos is implied, --exact refused (a flame's xforms have no inverse).
void run_flame_chaos_render(const RenderArgs& args) {
  check_mode_options(args);
  refuse_flame_flags(
      args, {"--view", "--margin", "--seamless", "--tiles", "--tile-offset", "--allow-expansive"});
  StopSignals signals;
  const OutputOptions output = checked_outputs(args);
  const flame::Flame f = flame::read_flame(args.preset);
  const cv::Size size =
      args.was_given("--size") ? size_option(args.size) : cv::Size{f.camera.width, f.camera.height};
  RenderArgs chaos = args;
  chaos.exact = args.map_method_given && args.exact;  // refused by render_still when asked for
  RenderOptions options = args.options;
  options.sampling.cancel = output.cancel;
  std::vector<OutputFile> staged;
  const StillResult still = render_picture(f, size, chaos, options, {}, output, staged);
  if (!args.save_flame.empty()) {
    OutputFile file(args.save_flame, output);
    write_file(file, flame::flame_xml(f));
    staged.push_back(std::move(file));
  }
  OutputFile image_file(args.output, output);
  write_image(image_file, still.image,
              {.bits = args.bits,
               .smallest = args.smallest,
               .metadata = flame_render_metadata(args.preset, to_string(args.mode),
                                                 options.sampling.seed)});
  staged.push_back(std::move(image_file));
  commit_together(staged);
  if (!args.quiet)
    print_summary(f.name.empty() ? args.preset : f.name, still.image.size(), chaos, still.stats);
}

// --mode, its choices and one line of help for each, from the modes' table (run/render_modes.h).
void add_mode_option(CLI::App& cmd, RenderMode& mode) {
  std::map<std::string, RenderMode> modes;
  std::string mode_help;
  for (const RenderModeInfo& info : render_modes()) {
    modes.emplace(info.name, info.mode);
    mode_help += fmt::format("{}{}: {}", mode_help.empty() ? "" : "; ", info.name, info.help);
  }
  cmd.add_option("--mode", mode, mode_help)
      ->transform(choice(modes))
      ->default_str("measure")
      ->option_text(choices_text(modes, "measure"));
}

// The options only some modes take (check_mode_options refuses them for the others), and
// --save-flame among them where the help has always listed it; returns --exact/--chaos, whose
// absence picks the mode's default.
CLI::Option* add_per_mode_options(CLI::App& cmd, RenderArgs& args) {
  cmd.add_option("--source", args.source,
                 "steal mode: image to steal colours from (any format OpenImageIO reads)");
  cmd.add_option("--colouring", args.colouring,
                 "steal mode: colouring IFS preset with as many maps, fitted to the source "
                 "(default: a tiling of the source for the number of maps)");
  // The exact descent is the default: faster than the chaos game for every shipped preset at
  // 720p and 1080p, and without noise (bench/README.md, steal_modes_bench).
  auto* map_method = cmd.add_flag(
      "--exact,!--chaos", args.exact,
      "tops/steal modes: top addresses by exact per-pixel descent (default; no noise or holes), "
      "or with --chaos by the chaos game, the paper's method (--quality points per pixel)");
  cmd.add_flag("--second-symbol", args.second_symbol,
               "tops mode: mix in the colour of the second symbol of the top address");
  cmd.add_option("--save-map", args.save_map,
                 "steal mode: also save the steal map, for `ifsfx apply MAP IMAGE`");
  cmd.add_option("--save-flame", args.save_flame,
                 "Also write the IFS as a flame file (.flame) that flam3, Apophysis, JWildfire "
                 "and Fractorium open, drawing its measure framed as this picture");
  cmd.add_option("--background", args.background,
                 "tops/steal modes: colour off the attractor in formats without alpha "
                 "(black, white, #rrggbb, R,G,B); PNG/TIFF/EXR get a transparent background. "
                 "A flame's measure: in place of the flame's own background, or 'transparent' "
                 "(alpha from the density, as flam3-render's transparency=1)")
      ->default_str("black");
  return map_method;
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand(
      "render", "Render an IFS preset or a fractal flame (.flame) to a still image");
  cmd->add_option(
         "preset", args->preset,
         "Preset: a shipped name (see `ifsfx presets`), a .toml/.ifs path, FILE.ifs:NAME, or a "
         "flame: FILE.flame, FILE.flame:NAME or FILE.flame:INDEX (its measure rendered as flam3 "
         "does, at its own size and quality unless --size and --quality are given; attractor, "
         "tops and steal through the chaos game)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output image; format by extension: .png (8/16-bit), .tif, .exr (float), .jpg")
      ->required();
  cmd->add_option("--size", args->size, "Output size WxH in pixels")->capture_default_str();
  add_mode_option(*cmd, args->mode);
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
  auto* map_method = add_per_mode_options(*cmd, *args);
  add_seamless_options(*cmd, args->tiles);
  cmd->callback([args, cmd, map_method, margin] {
    args->map_method_given = map_method->count() > 0;
    args->margin_given = margin->count() > 0;
    for (const CLI::Option* option : cmd->get_options())
      if (option->count() > 0) args->given.push_back(option->get_name());
    if (flame::is_flame_spec(args->preset) && args->mode == RenderMode::measure)
      run_flame_render(*args);
    else if (flame::is_flame_spec(args->preset))
      run_flame_chaos_render(*args);
    else
      run_render(*args);
  });
}

}  // namespace ifsfx::app
