// SPDX-License-Identifier: Apache-2.0
#include "farm/slurm.h"

#include <gtest/gtest.h>

#include <string>

namespace ifsfx::farm {
namespace {

// One line of `scontrol -o show job`, as Slurm 22.05 prints it (the fields that matter among
// some that do not, in its order).
std::string line(const std::string& job, const std::string& task, const std::string& state,
                 const std::string& reason, const std::string& exit_code) {
  return "JobId=" + job + " ArrayJobId=778 ArrayTaskId=" + task +
         " JobName=shards.sh UserId=root(0) GroupId=root(0) MCS_label=N/A Priority=4294901745 "
         "Nice=0 Account=(null) QOS=(null) JobState=" +
         state + " Reason=" + reason + " Dependency=(null) Requeue=1 Restarts=0 BatchFlag=1 " +
         "Reboot=0 ExitCode=" + exit_code + " RunTime=00:00:01 TimeLimit=UNLIMITED\n";
}

TEST(slurm, an_array_whose_last_task_ended_first_is_still_running) {
  // The first line is the array's own record, which is its highest task: seen on a real
  // cluster with task 3 done while task 2 still ran. Reading that line alone ended the wait early.
  const JobInfo info = job_info_of(
      line("778", "3", "COMPLETED", "None", "0:0") + line("781", "2", "RUNNING", "None", "0:0") +
      line("780", "1", "COMPLETED", "None", "0:0") + line("779", "0", "COMPLETED", "None", "0:0"));
  EXPECT_EQ(info.state, "RUNNING");
  EXPECT_FALSE(info.finished());
}

TEST(slurm, tasks_still_pending_keep_the_array_going) {
  const JobInfo info = job_info_of(line("770", "2-3", "PENDING", "Resources", "0:0") +
                                   line("772", "1", "COMPLETED", "None", "0:0") +
                                   line("771", "0", "COMPLETED", "None", "0:0"));
  EXPECT_EQ(info.state, "PENDING");
  EXPECT_FALSE(info.finished());
  EXPECT_FALSE(info.never_runs());
}

TEST(slurm, an_ended_array_reports_the_task_that_failed) {
  const JobInfo info = job_info_of(line("778", "3", "COMPLETED", "None", "0:0") +
                                   line("781", "2", "FAILED", "NonZeroExitCode", "3:0") +
                                   line("780", "1", "COMPLETED", "None", "0:0"));
  EXPECT_TRUE(info.finished());
  EXPECT_EQ(info.state, "FAILED");
  EXPECT_EQ(info.exit_code, 3);
  EXPECT_EQ(info.reason, "NonZeroExitCode");
}

TEST(slurm, an_array_completes_when_every_task_did) {
  const JobInfo info = job_info_of(line("778", "1", "COMPLETED", "None", "0:0") +
                                   line("779", "0", "COMPLETED", "None", "0:0"));
  EXPECT_TRUE(info.finished());
  EXPECT_EQ(info.state, "COMPLETED");
  EXPECT_EQ(info.exit_code, 0);
}

TEST(slurm, a_task_killed_by_a_signal_exits_with_128_plus_it) {
  const JobInfo info = job_info_of(line("779", "0", "CANCELLED", "None", "0:15"));
  EXPECT_TRUE(info.finished());
  EXPECT_EQ(info.exit_code, 128 + 15);
}

TEST(slurm, a_join_whose_dependency_failed_never_runs) {
  const JobInfo info =
      job_info_of(line("782", "N/A", "PENDING", "DependencyNeverSatisfied", "0:0"));
  EXPECT_FALSE(info.finished());
  EXPECT_TRUE(info.never_runs());
  EXPECT_FALSE(job_info_of(line("782", "N/A", "PENDING", "Dependency", "0:0")).never_runs());
}

TEST(slurm, nothing_printed_is_not_an_end) {
  EXPECT_FALSE(job_info_of("").finished());
  EXPECT_FALSE(job_info_of("slurm_load_jobs error: Invalid job id specified\n").finished());
}

}  // namespace
}  // namespace ifsfx::farm
