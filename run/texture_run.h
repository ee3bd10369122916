// SPDX-License-Identifier: Apache-2.0
// The work of `ifsfx texture`, without the terminal: the superIFS loaded, burnt in, and its
// frames written under the output policy (all put in place together at the end). The command
// prints its summary around it; `ifsfx studio` runs it as a render job with its own stop flag
// and progress bar, so that both write the same files.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/output_file.h"
#include "run/texture_options.h"
#include "superifs/superifs_file.h"

namespace ifsfx::app {

// What the caller adds to the arguments.
struct TextureRun {
  CancelToken cancel;  // polled by the burn-in, the steps and between frames
  InputFiles inputs;   // files no frame may replace, besides the command's own
  // After each frame is rendered (done of total), on the calling thread.
  std::function<void(int done, int total)> progress;
  // What the user should be told before the frames come (a movie's size made even): one line,
  // "note: ...".
  std::function<void(const std::string&)> note;
};

struct TextureOutcome {
  std::string name;  // the superIFS's name
  cv::Size size;
  int steps_done = 0;  // the sequence's steps, burn-in included
  int frames = 0;      // frames written
  int burn_in = 0;     // the steps before the first frame
  // --loop: whether the buffers came back to themselves within the burn-in (TextureSequence::
  // loop_closed); the loop repeats either way. True without --loop.
  bool loop_closed = true;
  double seconds = 0;
  std::vector<std::filesystem::path> files;  // the frames written, in order (or the movie)
};

// `ifsfx texture SUPERPRESET -o OUT [--frames N]` of `preset` (args.preset names its file, if
// any, for the output policy and the name of a superIFS without one): every output name is
// checked before the
// burn-in; a stop or a failure leaves every existing frame file as it was and no new one (a
// movie keeps the frames done as OUTPUT-STEM.partial.EXT, run/texture_movie.h). Throws
// ifsfx::Error for bad arguments and failed outputs (Error{interrupted} for a stop).
TextureOutcome write_textures(const SuperIfsPreset& preset, const TextureArgs& args,
                              const TextureRun& run);

}  // namespace ifsfx::app
