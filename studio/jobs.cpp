// SPDX-License-Identifier: Apache-2.0
#include "studio/jobs.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>

#include "ifs/error.h"
#include "studio/http.h"

namespace ifsfx::app {

using nlohmann::json;

const char* to_string(JobState state) noexcept {
  switch (state) {
    case JobState::queued:
      return "queued";
    case JobState::running:
      return "running";
    case JobState::done:
      return "done";
    case JobState::failed:
      return "failed";
    case JobState::cancelled:
      return "cancelled";
  }
  return "failed";
}

namespace {

bool pending(const Job& job) {
  return job.state == JobState::queued || job.state == JobState::running;
}

bool shares(const std::vector<std::string>& a, const std::vector<std::string>& b,
            std::string& which) {
  for (const auto& x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) {
      which = x;
      return true;
    }
  return false;
}

}  // namespace

std::atomic<bool>* JobContext::stop() const {
  return &job_.stop;
}

void JobContext::progress(double fraction, const std::string& phase, const std::string& detail) {
  std::lock_guard lock(lock_);
  job_.fraction = fraction < 0 ? -1 : std::min(fraction, 1.0);
  job_.phase = phase;
  job_.detail = detail;
}

void JobContext::add_file(const std::string& name) {
  std::lock_guard lock(lock_);
  job_.files.push_back(name);
}

void JobContext::set_result(json result) {
  std::lock_guard lock(lock_);
  job_.result = std::move(result);
}

void JobContext::set_preview(std::string png) {
  std::lock_guard lock(lock_);
  job_.preview = std::move(png);
}

JobQueue::JobQueue(int workers) {
  for (int i = 0; i < std::max(workers, 1); ++i) threads_.emplace_back([this] { worker(); });
}

JobQueue::~JobQueue() {
  stop_all();
  for (auto& t : threads_) t.join();
}

int JobQueue::submit(JobSpec spec, std::function<void(JobContext&)> work) {
  std::lock_guard lock(mutex_);
  if (stopping_) throw RequestError(503, "jobs: the server is stopping");
  std::size_t count = 0;
  for (const auto& job : jobs_) {
    if (!pending(*job)) continue;
    ++count;
    std::string file;
    if (shares(spec.writes, job->spec.writes, file) || shares(spec.writes, job->spec.reads, file) ||
        shares(spec.reads, job->spec.writes, file))
      throw RequestError(409, fmt::format("{}: in use by job {} ({}, {}); wait for it or cancel it",
                                          std::filesystem::path(file).filename().string(), job->id,
                                          job->spec.kind, to_string(job->state)));
  }
  if (count >= kMaxPending)
    throw RequestError(429, fmt::format("jobs: at most {} at once (got {} queued or running)",
                                        kMaxPending, count));
  auto job = std::make_shared<Job>();
  job->id = next_id_++;
  job->spec = std::move(spec);
  job->work = std::move(work);
  job->phase = "queued";
  jobs_.push_back(job);
  // Forget the oldest finished jobs beyond kMaxKept.
  std::size_t finished = 0;
  for (const auto& j : jobs_) finished += pending(*j) ? 0 : 1;
  for (auto it = jobs_.begin(); finished > kMaxKept && it != jobs_.end();) {
    if (!pending(**it)) {
      it = jobs_.erase(it);
      --finished;
    } else {
      ++it;
    }
  }
  wake_.notify_one();
  return job->id;
}

void JobQueue::worker() {
  // Lower than the request threads: the editor's renders come first (the threads a job starts
  // inherit it). Results do not depend on it (docs/design.md §7).
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 5);
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] {
        if (stopping_) return true;
        return std::any_of(jobs_.begin(), jobs_.end(),
                           [](const auto& j) { return j->state == JobState::queued; });
      });
      if (stopping_) return;
      job = *std::find_if(jobs_.begin(), jobs_.end(),
                          [](const auto& j) { return j->state == JobState::queued; });
      job->state = JobState::running;
      job->phase = "starting";
      job->started = std::chrono::steady_clock::now();
    }
    JobContext context(*job, mutex_);
    JobState state = JobState::done;
    std::string error;
    try {
      job->work(context);
    } catch (const Error& e) {
      state = e.kind() == ErrorKind::interrupted ? JobState::cancelled : JobState::failed;
      error = e.what();
    } catch (const std::exception& e) {
      state = JobState::failed;
      error = e.what();
    }
    std::lock_guard lock(mutex_);
    job->state = state;
    job->error = error;
    job->finished = std::chrono::steady_clock::now();
    if (state == JobState::done) {
      job->fraction = 1;
      job->phase = "done";
    } else {
      job->phase = to_string(state);
    }
    job->work = nullptr;  // what it held (a scratch file's guard) goes now
  }
}

json JobQueue::describe(const Job& job) const {
  using std::chrono::duration;
  const auto now = std::chrono::steady_clock::now();
  double seconds = 0;
  if (job.state == JobState::running) seconds = duration<double>(now - job.started).count();
  if (!pending(job) && job.started.time_since_epoch().count() != 0)
    seconds = duration<double>(job.finished - job.started).count();
  json out = {{"id", job.id},
              {"kind", job.spec.kind},
              {"title", job.spec.title},
              {"state", to_string(job.state)},
              {"progress", job.fraction < 0 ? json(nullptr) : json(job.fraction)},
              {"phase", job.phase},
              {"detail", job.detail},
              {"files", job.files},
              {"error", job.error},
              {"seconds", seconds},
              {"preview", !job.preview.empty()}};
  if (!job.result.is_null()) out["result"] = job.result;
  return out;
}

json JobQueue::list() const {
  std::lock_guard lock(mutex_);
  json out = json::array();
  for (auto it = jobs_.rbegin(); it != jobs_.rend(); ++it) out.push_back(describe(**it));
  return out;
}

std::shared_ptr<Job> JobQueue::find(int id) const {
  for (const auto& job : jobs_)
    if (job->id == id) return job;
  throw Error(ErrorKind::not_found, fmt::format("job: no such job (got {})", id));
}

json JobQueue::get(int id) const {
  std::lock_guard lock(mutex_);
  return describe(*find(id));
}

std::optional<std::string> JobQueue::preview(int id) const {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  if (job->preview.empty()) return std::nullopt;
  return job->preview;
}

void JobQueue::cancel(int id) {
  std::lock_guard lock(mutex_);
  const auto job = find(id);
  job->stop = true;
  if (job->state == JobState::queued) {
    job->state = JobState::cancelled;
    job->phase = "cancelled";
    job->error = "cancelled before it started";
    job->work = nullptr;
  }
}

void JobQueue::stop_all() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  for (const auto& job : jobs_) {
    job->stop = true;
    if (job->state == JobState::queued) {
      job->state = JobState::cancelled;
      job->phase = "cancelled";
      job->work = nullptr;
    }
  }
  wake_.notify_all();
}

}  // namespace ifsfx::app
