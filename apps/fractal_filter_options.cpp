// SPDX-License-Identifier: Apache-2.0
#include "apps/fractal_filter_options.h"

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"
#include "superifs/texture.h"

namespace ifsfx::app {

video::FractalSettings FractalFilterArgs::settings() const {
  video::FractalSettings s = engine;
  s.sampling.view = view_option(view);
  s.background = video::parse_background(background);
  s.sampling.cancel = StopSignals::token();  // Ctrl-C stops a map being computed
  return s;
}

void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args) {
  constexpr const char* kFractal = "Fractal";
  cmd.add_option("--preset", args.engine.preset,
                 "The drawing IFS F: a shipped name (see `ifsfx presets`), a .toml/.ifs path, or "
                 "FILE.ifs:NAME")
      ->capture_default_str()
      ->group(kFractal);
  cmd.add_option("--colouring", args.engine.colouring,
                 "The colouring IFS G on the frame (same map count as F; default: a tiling of the "
                 "frame)")
      ->group(kFractal);
  // The exact descent is the default: faster than the chaos game for every shipped preset at
  // 720p and 1080p, and without noise (bench/README.md, steal_modes_bench).
  cmd.add_flag("--exact,!--chaos", args.engine.exact,
               "Tops by exact per-pixel descent (default; no noise), or with --chaos by the chaos "
               "game, the paper's method (--quality points per pixel)")
      ->group(kFractal);
  cmd.add_option("--view", args.view,
                 "Plane rectangle x0,y0,x1,y1 shown on the frame (default: the attractor, "
                 "auto-framed); 0,0,1,1 puts the unit square on the whole frame")
      ->group(kFractal);
  cmd.add_option("--margin", args.engine.sampling.margin,
                 "Auto-framing margin, fraction of the larger side")
      ->capture_default_str()
      ->check(number_in(0, kMaxMargin))
      ->group(kFractal);
  cmd.add_option("--quality", args.engine.sampling.quality,
                 "--chaos: chaos-game points per output pixel")
      ->capture_default_str()
      ->check(number_in(0, kMaxQuality, true))
      ->group(kFractal);
  cmd.add_option("--mix", args.engine.mix,
                 "Weight of the original frame blended over the fractal, 0..1")
      ->capture_default_str()
      ->check(number_in(0, 1))
      ->group(kFractal);
  cmd.add_option("--background", args.background,
                 "Where the attractor does not cover: black, white, original, #rrggbb or R,G,B")
      ->capture_default_str()
      ->group(kFractal);
  constexpr const char* kAnimation = "Animation";
  cmd.add_option("--drift-amount", args.engine.drift_amount,
                 "--animate drift: largest excursion of a map coefficient (translations: "
                 "fraction of the attractor's size)")
      ->capture_default_str()
      ->check(number_in(0, video::kMaxDriftAmount))
      ->group(kAnimation);
  cmd.add_option("--drift-speed", args.engine.drift_speed,
                 "--animate drift: cycles per second of the slowest drift")
      ->capture_default_str()
      ->check(number_in(0, video::kMaxDriftSpeed))
      ->group(kAnimation);
  cmd.add_option("--loop", args.engine.loop,
                 "Animation: repeats every N frames, frame N being frame 0 again bit for bit and "
                 "the step into it as smooth as any other (0: never): the drift is periodic "
                 "noise, its slowest cycle a whole number of times per loop")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t{0}, kMaxLoop))
      ->group(kAnimation);
  cmd.add_option("--seed", args.engine.sampling.seed,
                 "Random seed: the same seed gives the same frames")
      ->capture_default_str()
      ->check(not_negative());
  add_threads_option(cmd, args.engine.sampling.threads);
}

}  // namespace ifsfx::app
