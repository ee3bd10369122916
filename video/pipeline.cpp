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
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  BoundedQueue<Frame> decoded(options.queue_depth);
  BoundedQueue<Frame> filtered(options.queue_depth);
  FirstError error;
  std::atomic<bool> interrupted{false};
  auto stop_requested = [&] {
    return options.stop != nullptr && options.stop->load(std::memory_order_relaxed);
  };

  const std::int64_t total = options.range.size_in(source.frame_count());

  std::jthread decoder([&] {
    try {
      // Frames before the range: passed over without making their images (a movie file seeks).
      const bool started = options.range.first == 0 || source.seek(options.range.first);
      while (started) {
        if (stop_requested()) {
          interrupted = true;
          break;
        }
        std::optional<Frame> frame = source.read();
        if (!frame) break;
        if (frame->index < options.range.first) continue;
        if (!options.range.contains(frame->index)) break;
        const bool last = options.range.last >= 0 && frame->index >= options.range.last;
        if (!decoded.push(std::move(*frame)) || last) break;
      }
    } catch (...) {
      error.set(std::current_exception());
    }
    decoded.finish();
  });

  std::jthread filterer([&] {
    try {
      while (std::optional<Frame> frame = decoded.pop()) {
        if (stop_requested()) {  // the output will be abandoned: no need to drain the queues
          interrupted = true;
          decoded.cancel();
          break;
        }
        cv::Mat image = filter(*frame);
        Frame out = std::move(*frame);  // index and time as the source gave them
        out.image = std::move(image);
        if (!filtered.push(std::move(out))) break;
      }
    } catch (...) {
      error.set(std::current_exception());
      decoded.cancel();  // the decoder may be waiting for room
    }
    filtered.finish();
  });

  PipelineResult result;
  auto report = [&](bool finished) {
    if (!options.progress) return;
    Progress p;
    p.done = result.frames_written;
    p.total = total;
    p.seconds = std::chrono::duration<double>(clock::now() - start).count();
    p.finished = finished;
    options.progress(p);
  };
  auto last_report = clock::now();
  try {
    while (std::optional<Frame> frame = filtered.pop()) {
      if (stop_requested()) {
        interrupted = true;
        filtered.cancel();
        decoded.cancel();
        break;
      }
      sink.write(*frame);
      ++result.frames_written;
      if (std::chrono::duration<double>(clock::now() - last_report).count() >=
          options.progress_interval) {
        last_report = clock::now();
        report(false);
      }
    }
  } catch (...) {
    error.set(std::current_exception());
    filtered.cancel();
    decoded.cancel();
  }
  decoder.join();
  filterer.join();

  std::exception_ptr first = error.get();
  // A stage that saw the stop request through a cancellation (an animation's map being built)
  // was stopped, not failed.
  if (first && stop_requested()) {
    try {
      std::rethrow_exception(first);
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::interrupted) first = nullptr, interrupted = true;
    } catch (...) {
    }
  }
  result.interrupted = interrupted;
  if (!first && !interrupted) {
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
  result.seconds = std::chrono::duration<double>(clock::now() - start).count();
  if (first) {
    if (result.partial.empty()) std::rethrow_exception(first);
    try {
      std::rethrow_exception(first);
    } catch (const Error& e) {
      throw Error(e.kind(), fmt::format("{}; {} frames kept in {}", e.what(), result.frames_written,
                                        result.partial.string()));
    }
  }
  report(true);
  return result;
}

}  // namespace ifsfx::video
