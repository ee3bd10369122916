// SPDX-License-Identifier: Apache-2.0
#include "apps/filter_options.h"

#include <map>

#include "apps/cli_options.h"
#include "ifs/error.h"

namespace ifsfx::app {

using video::Animate;

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
      ->check(CLI::Range(1, 100000))
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

void check_filter_rules(const FilterArgs& args) {
  if (args.fractal.engine.loop > 0 && args.animate == Animate::none)
    throw Error(ErrorKind::invalid_argument,
                "--loop: repeats an animation; add --animate drift or --animate superifs");
}

}  // namespace ifsfx::app
