// SPDX-License-Identifier: Apache-2.0
// The work of `ifsfx filter`, without the terminal: the arguments checked, the fractal loaded,
// the movie (or image sequence) opened and filtered through the pipeline into the output. The
// command draws its progress bar and summary around it; `ifsfx studio` runs it as a render job
// with its own stop flag and progress bar, so that both make the same frames.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/output_file.h"
#include "run/filter_options.h"
#include "video/frame_io.h"
#include "video/pipeline.h"
#include "video/progress.h"

namespace ifsfx::app {

// What the caller adds to the arguments.
struct FilterRun {
  // Set to stop: polled while the maps are built and between frames (Ctrl-C for the command);
  // a --preview window sets it when closed.
  std::atomic<bool>* stop = nullptr;
  video::ProgressCallback progress;  // on the encode thread
  double progress_interval = 0.25;   // seconds between reports
  InputFiles inputs;                 // files no output may replace, besides the command's own
  // What the user should be told before the frames come (a size made even): one line each,
  // "note: ...".
  std::function<void(const std::string&)> note;
};

struct FilterOutcome {
  video::PipelineResult result;  // frames written, interrupted, the partial movie kept
  std::string name;              // F's name, or the superIFS's with --animate superifs
  cv::Size size;                 // of the output frames
  video::Rational rate;          // the source's nominal rate
  std::int64_t stalls = 0;       // frames that waited for a keyframe (animations)
  bool constant_rate = false;    // a movie written at a constant rate, which
  std::int64_t repeated = 0;     // repeated
  std::int64_t dropped = 0;      // and dropped frames by their times
};

// The cheap checks of the arguments and the output name (--frames, the container and codec, the
// farm's --segment), before anything is opened; returns the frame range. Throws Error{parse} or
// Error{invalid_argument} naming the option.
video::FrameRange check_filter_args(const FilterArgs& args);

// `ifsfx filter INPUT -o OUTPUT` (or --preview) through `fractal` (F, G, the view and the look:
// FractalFilterArgs::settings for the command's flags; args.fractal's presets only name inputs
// no output may replace): cheap checks of the arguments and the output first, then the fractal,
// then the frames. args' interpolation and animation are set on the fractal's settings. A stop
// (run.stop) returns with result.interrupted and the frames done kept as a playable
// STEM.partial.EXT (result.partial), as the pipeline does; a stop before the first frame throws
// Error{interrupted} with nothing written. Throws ifsfx::Error for bad arguments, unreadable inputs
// and failed outputs, naming them.
FilterOutcome filter_movie(const FilterArgs& args, const engine::FractalSettings& fractal,
                           const FilterRun& run);

}  // namespace ifsfx::app
