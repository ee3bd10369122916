#include "apps/fractal_filter_options.h"

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "ifs/error.h"

namespace ifsfx::app {

StealMapOptions FractalFilterArgs::map_options() const {
  StealMapOptions o;
  o.view = view_option(view);
  o.margin = margin;
  o.exact = exact;
  o.quality = quality;
  o.seed = seed;
  o.threads = threads;
  return o;
}

video::FilterOptions FractalFilterArgs::filter_options() const {
  if (!(mix >= 0 && mix <= 1))
    throw Error(ErrorKind::invalid_argument, fmt::format("--mix: must be in [0, 1] (got {})", mix));
  video::FilterOptions o;
  o.mix = mix;
  o.background = video::parse_background(background, "--background");
  o.threads = threads;
  return o;
}

video::DriftOptions FractalFilterArgs::drift_options() const {
  return {.amount = drift_amount, .speed = drift_speed, .seed = seed};
}

void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args) {
  constexpr const char* kFractal = "Fractal";
  cmd.add_option("--preset", args.preset,
                 "The drawing IFS F: a shipped name (see `ifsfx presets`), a .toml/.ifs path, or "
                 "FILE.ifs:NAME")
      ->capture_default_str()
      ->group(kFractal);
  cmd.add_option("--colouring", args.colouring,
                 "The colouring IFS G on the frame (same map count as F; default: a tiling of the "
                 "frame)")
      ->group(kFractal);
  // The exact descent is the default: faster than the chaos game for every shipped preset at
  // 720p and 1080p, and without noise (bench/README.md, steal_modes_bench).
  cmd.add_flag("--exact,!--chaos", args.exact,
               "Tops by exact per-pixel descent (default; no noise), or with --chaos by the chaos "
               "game, the paper's method (--quality points per pixel)")
      ->group(kFractal);
  cmd.add_option("--view", args.view,
                 "Plane rectangle x0,y0,x1,y1 shown on the frame (default: the attractor, "
                 "auto-framed); 0,0,1,1 puts the unit square on the whole frame")
      ->group(kFractal);
  cmd.add_option("--margin", args.margin, "Auto-framing margin, fraction of the larger side")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 10.0))
      ->group(kFractal);
  cmd.add_option("--quality", args.quality, "--chaos: chaos-game points per output pixel")
      ->capture_default_str()
      ->group(kFractal);
  cmd.add_option("--mix", args.mix, "Weight of the original frame blended over the fractal, 0..1")
      ->capture_default_str()
      ->group(kFractal);
  cmd.add_option("--background", args.background,
                 "Where the attractor does not cover: black, original, #rrggbb or R,G,B")
      ->capture_default_str()
      ->group(kFractal);
  constexpr const char* kAnimation = "Animation";
  cmd.add_option("--drift-amount", args.drift_amount,
                 "--animate drift: largest excursion of a map coefficient (translations: "
                 "fraction of the attractor's size)")
      ->capture_default_str()
      ->group(kAnimation);
  cmd.add_option("--drift-speed", args.drift_speed,
                 "--animate drift: cycles per second of the slowest drift")
      ->capture_default_str()
      ->group(kAnimation);
  cmd.add_option("--seed", args.seed, "Random seed: the same seed gives the same frames")
      ->capture_default_str();
  cmd.add_option("--threads", args.threads, "Worker threads, 0 = all cores")->capture_default_str();
}

}  // namespace ifsfx::app
