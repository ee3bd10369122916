// SPDX-License-Identifier: Apache-2.0
#include "cli/option_groups.h"

#include <map>
#include <string>

#include "cli/cli_options.h"
#include "engine/drift.h"
#include "ifs/error.h"

namespace ifsfx::app {

using engine::Animate;

void add_fractal_filter_options(CLI::App& cmd, FractalFilterArgs& args) {
  constexpr const char* kFractal = "Fractal";
  cmd.add_option("--preset", args.preset,
                 "The drawing IFS F: a shipped name (see `ifsfx presets`), a .toml/.ifs path, "
                 "FILE.ifs:NAME, or a fractal flame, FILE.flame[:NAME] (through the chaos game)")
      ->capture_default_str()
      ->group(kFractal);
  cmd.add_option("--colouring", args.colouring,
                 "The colouring IFS G on the frame (same map count as F; default: a tiling of the "
                 "frame)")
      ->group(kFractal);
  // The exact descent is the default: faster than the chaos game for every shipped preset at
  // 720p and 1080p, and without noise (bench/README.md, steal_modes_bench).
  cmd.add_flag("--exact,!--chaos", args.engine.exact,
               "Tops by exact per-pixel descent (default; no noise), or with --chaos by the chaos "
               "game, the paper's method (--quality points per pixel); a flame always takes "
               "the chaos game")
      ->each([&args](const std::string&) { args.exact_given = true; })
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
      ->check(number_in(0, engine::kMaxDriftAmount))
      ->group(kAnimation);
  cmd.add_option("--drift-speed", args.engine.drift_speed,
                 "--animate drift: cycles per second of the slowest drift")
      ->capture_default_str()
      ->check(number_in(0, engine::kMaxDriftSpeed))
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

void add_filter_options(CLI::App& cmd, const std::shared_ptr<FilterArgs>& args) {
  add_fractal_filter_options(cmd, args->fractal);
  const std::map<std::string, Interpolation> interpolations{{"bilinear", Interpolation::bilinear},
                                                            {"nearest", Interpolation::nearest}};
  cmd.add_option("--interpolation", args->interpolation, "Lookup in the frame: bilinear or nearest")
      ->transform(choice(interpolations))
      ->default_str("bilinear")
      ->option_text(choices_text(interpolations, "bilinear"));
  cmd.add_option("--size", args->size,
                 "Output size WxH (default: the input's, upright). Encoders that code colour at "
                 "half resolution (H.264 in yuv420p, MPEG-4, ...) need even sides: an odd side "
                 "is made one pixel smaller, with a note on stderr");
  cmd.add_option("--codec", args->codec,
                 "Video encoder (libx264, h264, mpeg4, ffv1, ...; default by container: "
                 ".mp4/.mkv H.264 CRF 23, .avi MPEG-4 part 2)");
  cmd.add_option("--fps", args->fps, "Frame rate of an image sequence input")
      ->capture_default_str()
      ->check(number_in(0, 1000, true));
  cmd.add_flag("--skip-gaps", args->skip_gaps,
               "Image sequence input: go on past missing numbers (frame_0003 between 0002 and "
               "0004), holding the frame before for the missing time; without it a gap is an "
               "error naming the missing file");
  const std::map<std::string, video::FrameTiming> timings{{"auto", video::FrameTiming::automatic},
                                                          {"vfr", video::FrameTiming::keep},
                                                          {"cfr", video::FrameTiming::constant}};
  cmd.add_option("--fps-mode", args->timing,
                 "Frame times of a movie output. vfr: every frame keeps its input time, a "
                 "variable-rate input (phone, screen recording, dropped frames) stays in sync "
                 "with its audio; cfr: the input's nominal rate, each frame shown at its time, "
                 "repeated over gaps and dropped where two fall in one frame slot (ffmpeg "
                 "-fps_mode cfr); auto: vfr, or cfr where the container cannot keep times (.avi)")
      ->transform(choice(timings))
      ->default_str("auto")
      ->option_text(choices_text(timings, "auto"))
      ->each([args](const std::string&) { args->timing_given = true; });
  const std::map<std::string, Animate> animations{
      {"none", Animate::none}, {"drift", Animate::drift}, {"superifs", Animate::superifs}};
  cmd.add_option("--animate", args->animate,
                 "none: one fixed map; drift: map coefficients wander by fBm noise; superifs: a "
                 "V-variable step of --superifs per keyframe. Keyframes count input frames "
                 "(keyframe k at frame k·K), so a variable-rate input animates per frame, not "
                 "per second")
      ->transform(choice(animations))
      ->default_str("none")
      ->option_text(choices_text(animations, "none"))
      ->group("Animation");
  cmd.add_option("--keyframe-interval", args->keyframe_interval,
                 "Animation: frames between rebuilt maps, cross-faded in between (with --loop N: "
                 "ceil(N / this) keyframes spread evenly over the loop)")
      ->capture_default_str()
      ->check(CLI::Range(1, engine::kMaxKeyframeInterval))
      ->group("Animation");
  cmd.add_option("--superifs", args->superifs,
                 "--animate superifs: the superIFS (shipped name or .toml path); its own view and "
                 "colouring replace --preset, --colouring and --view")
      ->capture_default_str()
      ->group("Animation");
  cmd.add_option("--buffers", args->buffers, "--animate superifs: V, the number of buffers")
      ->capture_default_str()
      ->check(CLI::Range(1, 64))
      ->group("Animation");
}

void add_texture_options(CLI::App& cmd, const std::shared_ptr<TextureArgs>& args) {
  cmd.add_option("--size", args->size, "Output size WxH in pixels")->capture_default_str();
  cmd.add_option("-V,--buffers", args->count, "V, the number of buffers (V-variability)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxTextureBuffers));
  cmd.add_option("--steps", args->steps,
                 "Burn-in steps; 0 = enough that s^steps x size < 1/8 pixel for the largest "
                 "contraction factor s")
      ->capture_default_str()
      ->check(not_negative());
  cmd.add_option("--buffer", args->buffer, "The buffer shown, 1..V")->capture_default_str();
  const std::map<std::string, TextureMode> modes{{"attractor", TextureMode::attractor},
                                                 {"tops", TextureMode::tops},
                                                 {"steal", TextureMode::steal},
                                                 {"measure", TextureMode::measure}};
  cmd.add_option("--mode", args->mode,
                 "attractor: the set; tops: top addresses through a colour ramp; steal: colours "
                 "stolen from --source; measure: log-density of the measure")
      ->transform(choice(modes))
      ->default_str("attractor")
      ->option_text(choices_text(modes, "attractor"));
  cmd.add_option("--source", args->source, "Image colours are stolen from (steal mode)");
  cmd.add_option("--seed", args->seed, "Random seed: the same seed gives the same texture")
      ->capture_default_str()
      ->check(not_negative());
  add_threads_option(cmd, args->threads);
  cmd.add_option("--crossfade", args->crossfade,
                 "Frames per step of the sequence, blended between consecutive textures")
      ->capture_default_str();
  cmd.add_option("--bits", args->bits, "Bits per channel of PNG/TIFF output: 8 or 16")
      ->capture_default_str()
      ->check(CLI::IsMember({8, 16}));
  cmd.add_flag("-q,--quiet", args->quiet, "Do not print the summary line");
  add_seamless_options(cmd, args->tiles);
  // Loops in time and movie output (docs/loops.md).
  cmd.add_option("--loop", args->loop,
                 "A loop of N frames (--frames defaults to N): frame N is frame 0 again, bit for "
                 "bit, the superIFS choices periodic and the buffers closed, so the last frame "
                 "flows into the first; ceil(N / --crossfade) textures spread evenly (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t{0}, kMaxLoop));
  cmd.add_option("--fps", args->fps, "Frame rate of a movie output")
      ->capture_default_str()
      ->check(number_in(0, 1000, true))
      ->each([args](const std::string&) { args->fps_given = true; });
  cmd.add_option("--codec", args->codec,
                 "Video encoder of a movie output (default by container: .mp4/.mkv H.264, .webm "
                 "VP9, .gif GIF, .webp animated WebP; ffv1 in .mkv is lossless)");
}

}  // namespace ifsfx::app
