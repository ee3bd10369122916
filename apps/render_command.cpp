// `ifsfx render PRESET -o OUT`: an IFS rendered to a still image by the chaos game.
#include <cstdio>
#include <map>
#include <string>

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/commands.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/render.h"

namespace ifsfx::app {
namespace {

enum class Mode { attractor, measure };

struct RenderArgs {
  std::string preset;
  std::string output;
  std::string size = "1024x1024";
  Mode mode = Mode::measure;
  std::string view;
  double margin = 0.05;
  double quality = 64;
  int supersample = 1;
  double gamma = 2.2;
  double brightness = 4;
  std::uint64_t seed = 1;
  int threads = 0;
  int bits = 8;
  bool allow_expansive = false;
  bool quiet = false;
};

const char* mode_name(Mode mode) { return mode == Mode::attractor ? "attractor" : "measure"; }

void run_render(const RenderArgs& args) {
  const cv::Size size = size_option(args.size);
  check_writable_image(args.output);
  const IfsPreset preset = load_ifs(args.preset, {.allow_expansive = args.allow_expansive});

  RenderOptions options;
  options.view = view_option(args.view);
  options.margin = args.margin;
  options.quality = args.quality;
  options.supersample = args.supersample;
  options.gamma = args.gamma;
  options.brightness = args.brightness;
  options.seed = args.seed;
  options.threads = args.threads;

  RenderStats stats;
  cv::Mat image;
  switch (args.mode) {
    case Mode::attractor: image = render_attractor(preset.ifs, size, options, &stats); break;
    case Mode::measure: image = render_measure(preset.ifs, size, options, &stats); break;
  }

  WriteOptions write;
  write.bits = args.bits;
  write.metadata = {
      {"ifsfx:preset", preset.text},
      {"ifsfx:preset_name", preset.ifs.name},
      {"ifsfx:mode", mode_name(args.mode)},
      {"ifsfx:seed", std::to_string(args.seed)},
      {"ifsfx:view", fmt::format("{},{},{},{}", stats.view.x0, stats.view.y0, stats.view.x1,
                                 stats.view.y1)},
  };
  write_image(args.output, image, write);

  if (!args.quiet)
    std::printf("%s\n",
                fmt::format("{} ({}, {}x{}): {:.1f} M points in {:.3f} s ({:.0f} Mpts/s), "
                            "coverage {:.1f}% -> {}",
                            preset.ifs.name, mode_name(args.mode), size.width, size.height,
                            stats.points / 1e6, stats.seconds,
                            stats.points / 1e6 / std::max(stats.seconds, 1e-9),
                            100 * stats.coverage, args.output)
                    .c_str());
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Render an IFS preset to a still image");
  cmd->add_option("preset", args->preset,
                  "Preset: a shipped name (see `ifsfx presets`), a .toml/.ifs path, or FILE.ifs:NAME")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "Output image; format by extension: .png (8/16-bit), .tif, .exr (float), .jpg")
      ->required();
  cmd->add_option("--size", args->size, "Output size WxH in pixels")->capture_default_str();
  const std::map<std::string, Mode> modes{{"attractor", Mode::attractor},
                                          {"measure", Mode::measure}};
  cmd->add_option("--mode", args->mode,
                  "attractor: the set; measure: log-density of the invariant measure, "
                  "coloured by map")
      ->transform(CLI::CheckedTransformer(modes, CLI::ignore_case))
      ->default_str("measure");
  cmd->add_option("--view", args->view,
                  "Plane rectangle x0,y0,x1,y1 shown (default: the attractor, auto-framed)");
  cmd->add_option("--margin", args->margin, "Auto-framing margin, fraction of the larger side")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--quality", args->quality, "Chaos-game points per output pixel")
      ->capture_default_str();
  cmd->add_option("--supersample", args->supersample,
                  "Render at K times the size and box-filter down (measure mode)")
      ->capture_default_str();
  cmd->add_option("--gamma", args->gamma, "Display gamma of the tone map (measure mode)")
      ->capture_default_str();
  cmd->add_option("--brightness", args->brightness,
                  "k of the log-density tone map, relative to the mean density (measure mode)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed: the same seed gives the same image")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads, 0 = all cores")
      ->capture_default_str();
  cmd->add_option("--bits", args->bits, "Bits per channel of PNG/TIFF output: 8 or 16")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16}));
  cmd->add_flag("--allow-expansive", args->allow_expansive,
                "Accept maps with factor >= 1 when the IFS contracts on average");
  cmd->add_flag("-q,--quiet", args->quiet, "Do not print the summary line");
  cmd->callback([args] { run_render(*args); });
}

}  // namespace ifsfx::app
