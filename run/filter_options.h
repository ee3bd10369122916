// SPDX-License-Identifier: Apache-2.0
// The options of `ifsfx filter` that shape the picture and the output encoding, shared by the
// filter command and `ifsfx farm filter` (which hands them on, unchanged, to every shard).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "engine/fractal_engine.h"
#include "ifs/steal_map.h"
#include "run/fractal_filter_options.h"
#include "video/file_sink.h"

namespace ifsfx::app {

struct FilterArgs {
  std::string input;
  std::string output;
  bool preview = false;
  FractalFilterArgs fractal;
  Interpolation interpolation = Interpolation::bilinear;
  std::string size;
  std::string codec;
  std::string frames;
  double fps = 25;
  bool skip_gaps = false;
  video::FrameTiming timing = video::FrameTiming::automatic;
  bool timing_given = false;
  engine::Animate animate = engine::Animate::none;
  int keyframe_interval = engine::kDefaultKeyframeInterval;
  std::string superifs = "paper-fig4";
  int buffers = 3;
  bool quiet = false;
  bool segment = false;  // a farm shard's segment: the source's clock, no audio
};

// The rules between options that their parsing does not check and that `ifsfx farm filter` checks
// too before it submits anything: --loop repeats an animation, so it needs --animate.
void check_filter_rules(const FilterArgs& args);

// How a door names the loop and writes the animations (Python: "loop", "animate=\"drift\"").
struct LoopRuleNames {
  std::string loop = "--loop", drift = "--animate drift", superifs = "--animate superifs";
};
// A loop (loop > 0) repeats an animation: Error{invalid_argument} "LOOP: repeats an animation;
// add DRIFT or SUPERIFS" without one.
void check_loop_rule(std::int64_t loop, engine::Animate animate, const LoopRuleNames& names = {});

}  // namespace ifsfx::app
