// SPDX-License-Identifier: Apache-2.0
// The video pipeline: decode, filter and encode on three threads joined by bounded queues, so a
// slow stage sets the pace without the others stalling, and memory stays bounded.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "video/frame_io.h"
#include "video/progress.h"

namespace ifsfx::video {

// Source frames first..last, both included and counted from 0; last = -1 means to the end.
struct FrameRange {
  std::int64_t first = 0;
  std::int64_t last = -1;
  bool contains(std::int64_t i) const { return i >= first && (last < 0 || i <= last); }
  // How many of a source's `count` frames the range holds; -1 when the count is not known (-1).
  std::int64_t size_in(std::int64_t count) const {
    if (count < 0) return -1;
    return std::max<std::int64_t>(0, (last < 0 ? count : std::min(count, last + 1)) - first);
  }
};

// Parses "START:END" (both included), "START:" or ":END" (the --frames option); throws
// Error{parse} naming `what`.
FrameRange parse_frame_range(const std::string& text, const std::string& what = "frames");

// The filter applied to each frame, on the filter thread, in frame order. It returns the output
// image; the frame's index is its position in the source (not in the range), so an animation keyed
// on it gives the same frames whatever the range.
using FrameFilter = std::function<cv::Mat(const Frame&)>;

struct PipelineOptions {
  FrameRange range;
  std::size_t queue_depth = 4;              // frames waiting between two stages, per queue
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by a signal handler) to stop cleanly
  ProgressCallback progress;                // called on the encode thread; keep it quick
  double progress_interval = 0.25;          // seconds between reports (the last one always comes)
};

struct PipelineResult {
  std::int64_t frames_written = 0;
  bool interrupted = false;  // stopped by options.stop before the end of the range
  // Where the frames written were kept when the run did not complete (FrameSink::abandon: a
  // playable partial movie beside the output); empty when nothing was kept.
  std::filesystem::path partial;
  double seconds = 0;
};

// Runs source → filter → sink until the range ends or the source ends, then closes the sink (the
// output is put in place, holding exactly frames_written frames). When options.stop is set, or an
// error in any stage stops the others, the sink is abandoned instead: an existing output is left
// as it was and the frames written are kept apart where the sink can (FrameSink::abandon). A stop
// returns with `interrupted` and `partial` set; an error is rethrown, an ifsfx::Error with
// "; N frames kept in PARTIAL" added to its message — a damaged input thus ends with its error
// after saving what could be decoded.
//   auto result = run_pipeline(source, sink, [&](const Frame& f) { return filter(f.image); });
PipelineResult run_pipeline(FrameSource& source, FrameSink& sink, const FrameFilter& filter,
                            const PipelineOptions& options = {});

}  // namespace ifsfx::video
