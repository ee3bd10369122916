// SPDX-License-Identifier: Apache-2.0
// The studio's job queue (studio/jobs.h): jobs run in the order submitted, report progress,
// files, results and previews, stop when cancelled (at once when still queued), and never write a
// file another pending job uses.
#include "studio/jobs.h"

#include <chrono>
#include <future>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "studio/http.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

// The job's description once it is no longer queued or running (a wait, not a timing: the
// bound only keeps a broken queue from hanging the test).
json finished(const JobQueue& jobs, int id) {
  for (int i = 0; i < 20000; ++i) {
    json job = jobs.get(id);
    if (job["state"] != "queued" && job["state"] != "running") return job;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "job " << id << " never finished";
  return jobs.get(id);
}

// A job that waits until `release` is set (or it is cancelled), telling `started` it runs.
auto held(std::shared_future<void> release, std::promise<void>* started = nullptr) {
  return [release, started](JobContext& job) {
    if (started) started->set_value();
    while (release.wait_for(std::chrono::milliseconds(1)) != std::future_status::ready)
      job.cancel().check("held");
  };
}

TEST(job_queue, a_job_reports_progress_files_result_and_preview) {
  JobQueue jobs(1);
  std::promise<void> go;
  std::shared_future<void> release = go.get_future().share();
  std::promise<void> reported;
  const int id = jobs.submit({.kind = "still", .title = "fern.png", .writes = {"/f/fern.png"}},
                             [&](JobContext& job) {
                               job.progress(0.25, "rendering", "a quarter");
                               reported.set_value();
                               release.wait();
                               job.add_file("fern.png");
                               job.set_result({{"iou", 0.5}});
                               job.set_preview("PNG");
                             });
  reported.get_future().wait();
  const json running = jobs.get(id);
  EXPECT_EQ(running["state"], "running");
  EXPECT_EQ(running["progress"], 0.25);
  EXPECT_EQ(running["phase"], "rendering");
  EXPECT_EQ(running["detail"], "a quarter");
  EXPECT_EQ(running["preview"], false);
  go.set_value();
  const json done = finished(jobs, id);
  EXPECT_EQ(done["state"], "done");
  EXPECT_EQ(done["progress"], 1.0);
  EXPECT_EQ(done["phase"], "done");
  EXPECT_EQ(done["files"], json::array({"fern.png"}));
  EXPECT_EQ(done["result"]["iou"], 0.5);
  EXPECT_EQ(done["title"], "fern.png");
  EXPECT_EQ(done["kind"], "still");
  EXPECT_EQ(jobs.preview(id), "PNG");
}

TEST(job_queue, one_worker_runs_jobs_in_the_order_submitted) {
  JobQueue jobs(1);
  std::mutex mutex;
  std::vector<int> order;
  std::vector<int> ids;
  for (int k = 0; k < 5; ++k)
    ids.push_back(jobs.submit({.kind = "still", .title = std::to_string(k)}, [&, k](JobContext&) {
      std::lock_guard lock(mutex);
      order.push_back(k);
    }));
  for (int id : ids) EXPECT_EQ(finished(jobs, id)["state"], "done");
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(ids, (std::vector<int>{1, 2, 3, 4, 5}));
  // The list is newest first.
  const json list = jobs.list();
  ASSERT_EQ(list.size(), 5u);
  EXPECT_EQ(list[0]["id"], 5);
  EXPECT_EQ(list[4]["id"], 1);
}

TEST(job_queue, a_cancelled_queued_job_never_runs_and_a_running_one_stops) {
  JobQueue jobs(1);
  std::promise<void> never;
  std::promise<void> started;
  const int running = jobs.submit({.kind = "filter"}, held(never.get_future().share(), &started));
  bool ran = false;
  const int queued = jobs.submit({.kind = "still"}, [&](JobContext&) { ran = true; });
  started.get_future().wait();
  jobs.cancel(queued);
  const json dropped = jobs.get(queued);
  EXPECT_EQ(dropped["state"], "cancelled");
  EXPECT_EQ(dropped["error"], "cancelled before it started");
  jobs.cancel(running);
  const json stopped = finished(jobs, running);
  EXPECT_EQ(stopped["state"], "cancelled");
  EXPECT_FALSE(ran);
}

TEST(job_queue, a_job_that_throws_fails_with_its_message) {
  JobQueue jobs(1);
  const int id = jobs.submit({.kind = "fit"}, [](JobContext&) {
    throw Error(ErrorKind::invalid_argument, "maps: at most 32 (got 40)");
  });
  const json job = finished(jobs, id);
  EXPECT_EQ(job["state"], "failed");
  EXPECT_EQ(job["error"], "maps: at most 32 (got 40)");
}

TEST(job_queue, a_file_in_use_by_a_pending_job_is_refused_with_409) {
  JobQueue jobs(1);
  std::promise<void> go;
  std::shared_future<void> release = go.get_future().share();
  std::promise<void> started;
  jobs.submit({.kind = "filter", .writes = {"/f/out.mp4"}, .reads = {"/f/in.mp4"}},
              held(release, &started));
  started.get_future().wait();
  const auto status_of_submit = [&](JobSpec spec) {
    try {
      jobs.submit(std::move(spec), [](JobContext&) {});
    } catch (const RequestError& e) {
      return e.status;
    }
    return 200;
  };
  EXPECT_EQ(status_of_submit({.kind = "still", .writes = {"/f/out.mp4"}}), 409);  // both write
  EXPECT_EQ(status_of_submit({.kind = "still", .writes = {"/f/in.mp4"}}), 409);   // it reads it
  EXPECT_EQ(status_of_submit({.kind = "still", .reads = {"/f/out.mp4"}}), 409);   // it writes it
  EXPECT_EQ(status_of_submit({.kind = "still", .reads = {"/f/in.mp4"}}), 200);    // both read
  try {
    jobs.submit({.kind = "still", .writes = {"/f/out.mp4"}}, [](JobContext&) {});
    ADD_FAILURE() << "no error";
  } catch (const RequestError& e) {
    EXPECT_STREQ(e.what(), "out.mp4: in use by job 1 (filter, running); wait for it or cancel it");
  }
  go.set_value();
  EXPECT_EQ(finished(jobs, 1)["state"], "done");
  EXPECT_EQ(status_of_submit({.kind = "still", .writes = {"/f/out.mp4"}}), 200);  // free again
}

TEST(job_queue, at_most_kMaxPending_jobs_wait_then_429) {
  JobQueue jobs(1);
  std::promise<void> go;
  std::shared_future<void> release = go.get_future().share();
  for (std::size_t k = 0; k < JobQueue::kMaxPending; ++k)
    jobs.submit({.kind = "still"}, held(release));
  try {
    jobs.submit({.kind = "still"}, [](JobContext&) {});
    ADD_FAILURE() << "no error";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.status, 429);
    EXPECT_STREQ(e.what(), "jobs: at most 16 at once (got 16 queued or running)");
  }
  go.set_value();
}

TEST(job_queue, an_unknown_job_is_not_found) {
  JobQueue jobs(1);
  try {
    jobs.get(99);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_STREQ(e.what(), "job: no such job (got 99)");
  }
  EXPECT_THROW(jobs.cancel(99), Error);
}

TEST(job_queue, stop_all_stops_the_running_job_and_refuses_new_ones) {
  JobQueue jobs(1);
  std::promise<void> never;
  std::promise<void> started;
  const int id = jobs.submit({.kind = "filter"}, held(never.get_future().share(), &started));
  started.get_future().wait();
  jobs.stop_all();
  EXPECT_EQ(finished(jobs, id)["state"], "cancelled");
  try {
    jobs.submit({.kind = "still"}, [](JobContext&) {});
    ADD_FAILURE() << "no error";
  } catch (const RequestError& e) {
    EXPECT_EQ(e.status, 503);
  }
}

}  // namespace
}  // namespace ifsfx::app
