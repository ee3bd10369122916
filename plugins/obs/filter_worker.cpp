// SPDX-License-Identifier: Apache-2.0
#include "plugins/obs/filter_worker.h"

#include <exception>

namespace ifsfx::obs {
namespace {

// Copies the planes of `from` into `to`, reusing its buffers when they fit.
void copy_frame(const FrameData& from, FrameData& to) {
  to.format = from.format;
  to.size = from.size;
  to.yuv = from.yuv;
  to.flip = from.flip;
  to.timestamp = from.timestamp;
  to.planes.resize(from.planes.size());
  for (std::size_t i = 0; i < from.planes.size(); ++i) from.planes[i].copyTo(to.planes[i]);
}

bool ready(const std::future<std::unique_ptr<PictureMaker>>& f) {
  return f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

}  // namespace

FilterWorker::FilterWorker(double frame_rate)
    : frame_rate_(frame_rate), thread_([this] { run(); }) {}

FilterWorker::~FilterWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
  if (build_.valid()) build_.wait();  // cancelled by stop_ within a fraction of a second
}

void FilterWorker::configure(const PluginSettings& settings) {
  std::lock_guard lock(mutex_);
  wanted_.settings = settings;
  wanted_.settings.engine.sampling.cancel = CancelToken(&stop_);
  ++wanted_.generation;
  status_.clear();
}

void FilterWorker::reject(const std::string& message) {
  fail(message);
}

void FilterWorker::fail(const std::string& message) {
  std::lock_guard lock(mutex_);
  status_ = message;
}

std::string FilterWorker::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

WorkerStats FilterWorker::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

Shown FilterWorker::exchange(FrameData& frame) {
  copy_frame(frame, spare_);  // outside the lock: this buffer is this thread's own
  std::shared_ptr<const Picture> newest;
  {
    std::lock_guard lock(mutex_);
    ++stats_.frames;
    if (has_pending_) ++stats_.dropped;
    std::swap(spare_, pending_);
    pending_at_ = Clock::now();
    has_pending_ = true;
    newest = newest_;
    const bool fits = newest && newest->frame.format == frame.format &&
                      newest->frame.size == frame.size &&
                      newest->frame.planes.size() == frame.planes.size();
    if (!fits) {
      ++stats_.passed;
      newest.reset();
    } else {
      if (shown_any_ && newest->frame.timestamp == last_shown_) ++stats_.repeated;
      shown_any_ = true;
      last_shown_ = newest->frame.timestamp;
    }
  }
  wake_.notify_one();
  if (!newest) return {};
  for (std::size_t i = 0; i < frame.planes.size(); ++i)
    newest->frame.planes[i].copyTo(frame.planes[i]);
  return {true, newest->frame.timestamp, newest->submitted, newest->finished};
}

void FilterWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || has_pending_; });
    if (stop_) return;
    std::swap(job_, pending_);
    has_pending_ = false;
    const Clock::time_point submitted = pending_at_;
    const Wanted wanted = wanted_;
    lock.unlock();
    try {
      make(job_, submitted, wanted);
    } catch (const std::exception& e) {
      fail(e.what());
    }
    lock.lock();
  }
}

void FilterWorker::make(FrameData& job, Clock::time_point submitted, const Wanted& wanted) {
  PictureMaker* maker = maker_for(wanted, job.size);
  if (maker == nullptr) return;
  // The animation's clock is the source's: seconds since its first frame (or since it went
  // back, as a media source does when it loops).
  if (!first_timestamp_ || job.timestamp < *first_timestamp_) first_timestamp_ = job.timestamp;
  const double seconds = static_cast<double>(job.timestamp - *first_timestamp_) * 1e-9;
  auto picture = std::make_shared<Picture>();
  picture->frame = {job.format, job.size, job.yuv, job.flip, job.timestamp, {}};
  picture->submitted = submitted;
  // The fractal of the upright picture, stored as the frame is.
  cv::Mat in = to_engine(job.format, job.planes, job.yuv, job.size), out;
  if (job.flip) cv::flip(in, in, 0);
  maker->make(in, seconds, out);
  if (job.flip) cv::flip(out, out, 0);
  for (const cv::Mat& p : job.planes) picture->frame.planes.emplace_back(p.size(), p.type());
  from_engine(out, job.format, job.yuv, picture->frame.planes);
  picture->finished = Clock::now();
  std::lock_guard lock(mutex_);
  newest_ = std::move(picture);
  ++stats_.filtered;
}

PictureMaker* FilterWorker::maker_for(const Wanted& wanted, cv::Size size) {
  if (wanted.generation < 0) return nullptr;
  if (maker_ && maker_->serves(wanted.settings, size, frame_rate_)) {
    if (maker_->settings().engine != wanted.settings.engine) maker_->set_look(wanted.settings);
    return maker_.get();
  }
  // A build for settings or a size no longer wanted is let finish (it cannot be stopped alone)
  // and thrown away; the one wanted starts after it.
  if (build_.valid() && (build_generation_ != wanted.generation || build_size_ != size)) {
    if (!ready(build_))
      return maker_ && maker_->serves(maker_->settings(), size, frame_rate_) ? maker_.get()
                                                                             : nullptr;
    try {
      build_.get();
    } catch (const std::exception&) {
    }
  }
  if (!build_.valid() && failed_generation_ != wanted.generation) {
    build_generation_ = wanted.generation;
    build_size_ = size;
    build_ = std::async(std::launch::async, [s = wanted.settings, size, rate = frame_rate_] {
      return std::make_unique<PictureMaker>(s, size, rate);
    });
  }
  if (build_.valid() && ready(build_)) {
    try {
      maker_ = build_.get();
      return maker_.get();
    } catch (const std::exception& e) {
      failed_generation_ = wanted.generation;
      fail(e.what());
    }
  }
  // The last good maps until the new ones are ready, if they are for this size.
  return maker_ && maker_->serves(maker_->settings(), size, frame_rate_) ? maker_.get() : nullptr;
}

}  // namespace ifsfx::obs
