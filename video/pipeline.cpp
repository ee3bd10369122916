// SPDX-License-Identifier: Apache-2.0
#include "video/pipeline.h"

#include <charconv>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "ifs/error.h"
#include "video/bounded_queue.h"

namespace ifsfx::video {

namespace {

std::int64_t parse_index(std::string_view text, const std::string& what, const std::string& whole) {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < 0)
    throw Error(ErrorKind::parse,
                fmt::format("{}: expected START:END frame numbers from 0 (got '{}')", what, whole));
  return value;
}

// The first error raised by any stage; the others are consequences of stopping.
class FirstError {
 public:
  void set(std::exception_ptr e) {
    std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(e);
  }
  std::exception_ptr get() {
    std::lock_guard lock(mutex_);
    return error_;
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
};

using Clock = std::chrono::steady_clock;

// What the three stages share: the queues between them, the first error, the stop.
struct Stages {
  explicit Stages(const PipelineOptions& o)
      : options(o), decoded(o.queue_depth), filtered(o.queue_depth) {}
  bool stop_requested() const {
    return options.stop != nullptr && options.stop->load(std::memory_order_relaxed);
  }

  const PipelineOptions& options;
  BoundedQueue<Frame> decoded;
  BoundedQueue<Frame> filtered;
  FirstError error;
  std::atomic<bool> interrupted{false};
};

// The decode thread: the frames of the range into `decoded`.
void decode(Stages& s, FrameSource& source) {
  const FrameRange& range = s.options.range;
  try {
    // Frames before the range: passed over without making their images (a movie file seeks).
    const bool started = range.first == 0 || source.seek(range.first);
    while (started) {
      if (s.stop_requested()) {
        s.interrupted = true;
        break;
      }
      std::optional<Frame> frame = source.read();
      if (!frame) break;
      if (frame->index < range.first) continue;
      if (!range.contains(frame->index)) break;
      const bool last = range.last >= 0 && frame->index >= range.last;
      if (!s.decoded.push(std::move(*frame)) || last) break;
    }
  } catch (...) {
    s.error.set(std::current_exception());
  }
  s.decoded.finish();
}

// The filter thread: `decoded` through the filter into `filtered`, in order.
void filter_frames(Stages& s, const FrameFilter& filter) {
  try {
    while (std::optional<Frame> frame = s.decoded.pop()) {
      if (s.stop_requested()) {  // the output will be abandoned: no need to drain the queues
        s.interrupted = true;
        s.decoded.cancel();
        break;
      }
      cv::Mat image = filter(*frame);
      Frame out = std::move(*frame);  // index and time as the source gave them
      out.image = std::move(image);
      if (!s.filtered.push(std::move(out))) break;
    }
  } catch (...) {
    s.error.set(std::current_exception());
    s.decoded.cancel();  // the decoder may be waiting for room
  }
  s.filtered.finish();
}

// The progress reports: one every progress_interval seconds, and the last.
class Reporter {
 public:
  Reporter(const PipelineOptions& options, std::int64_t total, Clock::time_point start)
      : options_(options), total_(total), start_(start), last_(Clock::now()) {}

  void at_interval(std::int64_t done) {
    if (std::chrono::duration<double>(Clock::now() - last_).count() >= options_.progress_interval) {
      last_ = Clock::now();
      report(done, false);
    }
  }
  void report(std::int64_t done, bool finished) const {
    if (!options_.progress) return;
    Progress p;
    p.done = done;
    p.total = total_;
    p.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    p.finished = finished;
    options_.progress(p);
  }

 private:
  const PipelineOptions& options_;
  std::int64_t total_;
  Clock::time_point start_;
  Clock::time_point last_;
};

// The encode stage, on the calling thread: `filtered` into the sink.
void encode(Stages& s, FrameSink& sink, Reporter& reporter, PipelineResult& result) {
  try {
    while (std::optional<Frame> frame = s.filtered.pop()) {
      if (s.stop_requested()) {
        s.interrupted = true;
        s.filtered.cancel();
        s.decoded.cancel();
        break;
      }
      sink.write(*frame);
      ++result.frames_written;
      reporter.at_interval(result.frames_written);
    }
  } catch (...) {
    s.error.set(std::current_exception());
    s.filtered.cancel();
    s.decoded.cancel();
  }
}

// The first error of the stages, if any. A stage that saw the stop request through a
// cancellation (an animation's map being built) was stopped, not failed.
std::exception_ptr stage_error(Stages& s) {
  std::exception_ptr first = s.error.get();
  if (first && s.stop_requested()) {
    try {
      std::rethrow_exception(first);
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::interrupted) first = nullptr, s.interrupted = true;
    } catch (...) {
    }
  }
  return first;
}

// Rethrows `error`, saying where the frames written were kept, if anywhere.
[[noreturn]] void rethrow_with_partial(std::exception_ptr error, const PipelineResult& result) {
  if (result.partial.empty()) std::rethrow_exception(error);
  try {
    std::rethrow_exception(error);
  } catch (const Error& e) {
    throw Error(e.kind(), fmt::format("{}; {} frames kept in {}", e.what(), result.frames_written,
                                      result.partial.string()));
  }
}

}  // namespace

FrameRange parse_frame_range(const std::string& text, const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos)
    throw Error(ErrorKind::parse,
                fmt::format("{}: expected START:END, START: or :END (got '{}')", what, text));
  FrameRange range;
  const std::string_view all(text);
  const auto first = all.substr(0, colon);
  const auto last = all.substr(colon + 1);
  if (!first.empty()) range.first = parse_index(first, what, text);
  if (!last.empty()) range.last = parse_index(last, what, text);
  if (range.last >= 0 && range.last < range.first)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: END must not be before START (got '{}')", what, text));
  return range;
}

PipelineResult run_pipeline(FrameSource& source, FrameSink& sink, const FrameFilter& filter,
                            const PipelineOptions& options) {
  const auto start = Clock::now();
  Stages stages(options);
  Reporter reporter(options, options.range.size_in(source.frame_count()), start);

  std::jthread decoder([&] { decode(stages, source); });
  std::jthread filterer([&] { filter_frames(stages, filter); });
  PipelineResult result;
  encode(stages, sink, reporter, result);
  decoder.join();
  filterer.join();

  std::exception_ptr first = stage_error(stages);
  result.interrupted = stages.interrupted;
  if (!first && !result.interrupted) {
    try {
      sink.close();
    } catch (...) {
      first = std::current_exception();
    }
  } else {
    // The output did not complete: an existing one stays as it was; what was written is kept
    // apart where that is useful.
    result.partial = sink.abandon();
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (first) rethrow_with_partial(first, result);
  reporter.report(result.frames_written, true);
  return result;
}

}  // namespace ifsfx::video
