// SPDX-License-Identifier: Apache-2.0
#include "video/camera_pipeline.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "ifs/error.h"

namespace ifsfx::video {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Closes every sink; the first failure is rethrown after all have been tried.
void close_all(const std::vector<FrameSink*>& sinks) {
  std::exception_ptr first;
  for (FrameSink* sink : sinks) {
    try {
      sink->close();
    } catch (...) {
      if (!first) first = std::current_exception();
    }
  }
  if (first) std::rethrow_exception(first);
}

void summarise(std::vector<double>& latencies, double process_sum, CameraStats& stats) {
  if (latencies.empty()) return;
  double sum = 0;
  for (double l : latencies) sum += l;
  stats.latency_mean = sum / latencies.size();
  stats.process_mean = process_sum / latencies.size();
  std::sort(latencies.begin(), latencies.end());
  stats.latency_max = latencies.back();
  stats.latency_p95 = latencies[std::min(latencies.size() - 1, latencies.size() * 95 / 100)];
}

}  // namespace

CameraStats run_camera(LiveSource& source, const CameraFilter& filter,
                       const std::vector<FrameSink*>& sinks, const CameraLoopOptions& options,
                       const CameraObserver& observer) {
  CameraStats stats;
  std::vector<double> latencies;
  double process_sum = 0;
  Clock::time_point first_out{}, last_out{};
  const auto update = [&] {
    stats.dropped = source.dropped();
    stats.seconds = stats.frames > 0 ? seconds_between(first_out, last_out) : 0;
  };
  try {
    while (options.max_frames <= 0 || stats.frames < options.max_frames) {
      if (options.stop != nullptr && options.stop->load()) break;
      std::optional<Frame> frame = source.read();
      if (!frame) break;
      const Clock::time_point dequeued = Clock::now();
      Frame out;
      out.image = filter ? filter(*frame) : frame->image;
      out.index = frame->index;
      out.timestamp = frame->timestamp;
      for (FrameSink* sink : sinks) sink->write(out);
      last_out = Clock::now();
      if (stats.frames == 0) first_out = last_out;
      ++stats.frames;
      const auto captured =
          source.clock_origin() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(frame->timestamp));
      latencies.push_back(seconds_between(captured, last_out));
      process_sum += seconds_between(dequeued, last_out);
      update();
      if (observer && !observer(out, stats)) break;
    }
  } catch (const Error& e) {
    // A computation that saw the stop request (a map being built) ends the session the ordinary
    // way, like the stop flag itself.
    const bool stopped =
        e.kind() == ErrorKind::interrupted && options.stop != nullptr && options.stop->load();
    if (!stopped) {
      for (FrameSink* sink : sinks) sink->abandon();
      throw;
    }
  } catch (...) {
    // The outputs did not complete: each keeps what it can apart from its target (a recording
    // becomes a playable partial movie), then the fault that stopped the loop is reported.
    for (FrameSink* sink : sinks) sink->abandon();
    throw;
  }
  close_all(sinks);
  update();
  summarise(latencies, process_sum, stats);
  return stats;
}

}  // namespace ifsfx::video
