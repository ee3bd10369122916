// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio`'s render jobs (docs/studio.md): long work — a full-size still, the movie filter,
// a texture sequence, a fit — run by a small pool of job threads beside the editor, whose own
// renders run on the request threads, so a long job never freezes the editor. Each job has its
// own stop flag, progress and result; the queue's state is read and changed under one lock only,
// so any number of tabs may start, watch and cancel jobs at once.
//
//   JobQueue jobs(2);
//   int id = jobs.submit({.kind = "still", .title = "fern.png", .writes = {"/f/fern.png"}},
//                        [](JobContext& job) { ...; job.progress(0.5, "rendering"); ... });
//   jobs.cancel(id);
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "ifs/cancel.h"

namespace ifsfx::app {

enum class JobState { queued, running, done, failed, cancelled };
const char* to_string(JobState state) noexcept;

// What a job is and which files it touches: no two jobs at once may write the same file, or
// write a file another reads (paths as the job will open them, in the folder).
struct JobSpec {
  std::string kind;   // "still", "filter", "texture", "fit"
  std::string title;  // for the list: the output's name, the target's
  std::vector<std::string> writes;
  std::vector<std::string> reads;
};

struct Job;

// What a running job sees: its stop flag, and where it reports progress and results. Reports
// are cheap (one lock); call them from the job's thread or its callbacks.
class JobContext {
 public:
  JobContext(Job& job, std::mutex& lock) : job_(job), lock_(lock) {}
  // The stop flag, set by cancel() and when the server stops.
  std::atomic<bool>* stop() const;
  CancelToken cancel() const { return CancelToken(stop()); }
  // `fraction` of the work done (0..1; negative: not known), the phase and a line of detail.
  void progress(double fraction, const std::string& phase, const std::string& detail = {});
  // A file of the folder the job made (by its plain name), listed with the job.
  void add_file(const std::string& name);
  // What the job gives back besides files (a fit's preset and report).
  void set_result(nlohmann::json result);
  // Bytes kept with the job and served as GET /api/jobs/ID/preview (a fit's preview PNG).
  void set_preview(std::string png);

 private:
  Job& job_;
  std::mutex& lock_;  // the queue's
};

struct Job {
  int id = 0;
  JobSpec spec;
  std::function<void(JobContext&)> work;
  std::atomic<bool> stop{false};
  // Below: under the queue's lock.
  JobState state = JobState::queued;
  double fraction = -1;
  std::string phase, detail, error;
  std::vector<std::string> files;
  nlohmann::json result;
  std::string preview;
  std::chrono::steady_clock::time_point started, finished;
};

class JobQueue {
 public:
  static constexpr std::size_t kMaxPending = 16;  // queued or running jobs
  static constexpr std::size_t kMaxKept = 64;     // finished jobs listed

  // `workers` job threads (at least 1), started at once; they run at a lower priority (nice 5)
  // than the request threads, so that the editor's renders come first.
  explicit JobQueue(int workers);
  ~JobQueue();  // stop_all(), then joins the threads
  JobQueue(const JobQueue&) = delete;
  JobQueue& operator=(const JobQueue&) = delete;

  // Queues a job and returns its number. Throws RequestError 409 naming the file when it would
  // write a file a pending job reads or writes, or read one a pending job writes, and 429 when
  // kMaxPending jobs are pending.
  int submit(JobSpec spec, std::function<void(JobContext&)> work);

  // The jobs, newest first, as the page reads them (docs/studio.md), or one job; Error{not_found}
  // for an unknown number.
  nlohmann::json list() const;
  nlohmann::json get(int id) const;
  std::optional<std::string> preview(int id) const;

  // Asks job `id` to stop (a queued job is dropped at once). Error{not_found} when unknown.
  void cancel(int id);
  // Asks every job to stop and drops the queued ones; the threads end once their jobs have.
  void stop_all();

 private:
  void worker();
  nlohmann::json describe(const Job& job) const;
  std::shared_ptr<Job> find(int id) const;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::shared_ptr<Job>> jobs_;  // every job kept, oldest first
  int next_id_ = 1;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace ifsfx::app
