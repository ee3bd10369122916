// SPDX-License-Identifier: Apache-2.0
// A farm job's batch scripts, their submission, and how the job stands: the Slurm side of
// `ifsfx farm`. The scripts are written for people to read (and submit by hand with submit.sh).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "farm/shard_plan.h"
#include "ifs/cancel.h"

namespace ifsfx::farm {

// The sbatch settings of every job of a farm run.
struct SlurmOptions {
  std::string partition;           // --partition; empty: the cluster's default
  std::string time;                // --time limit per task, e.g. 2:00:00
  int cpus_per_task = 0;           // --cpus-per-task; 0: the cluster's default
  std::string mem;                 // --mem per task, e.g. 8G
  std::vector<std::string> extra;  // more sbatch arguments, handed on unchanged
};

// The command of shard `i` (argv, run as it is), and of the join (empty: none, texture jobs).
struct JobCommands {
  std::function<std::vector<std::string>(std::size_t)> shard;
  std::vector<std::string> join;
};

// Writes shards.sh (one Slurm array job: task i runs commands.shard(i), then marks the shard
// done), join.sh (commands.join, after all shards succeeded) and submit.sh (submits both as
// `ifsfx farm ... --submit` does) into plan.folder.
void write_scripts(const FarmPlan& plan, const SlurmOptions& options, const JobCommands& commands);

// The job ids of the latest submission, kept in jobs.txt ("array ID" / "join ID").
struct Submission {
  std::string array;  // empty when no shard was submitted (resume with all shards done)
  std::string join;   // empty for texture jobs
};

// Submits the array tasks `shards` (none: the join alone) and, with_join, the join, dependent on
// them by afterok; the scripts carry the sbatch settings. Records the ids in jobs.txt. Throws
// Error{io} with sbatch's message when a submission fails (a submitted array is cancelled again,
// so nothing runs half-submitted).
Submission submit(const FarmPlan& plan, const std::vector<std::size_t>& shards, bool with_join);
std::optional<Submission> read_submission(const FarmPlan& plan);

enum class ShardState { done, queued, failed, not_run };

struct ShardStatus {
  ShardState state = ShardState::not_run;
  std::string queue_state;  // PENDING, RUNNING, ... for queued shards
  std::string last_line;    // failed: the last line of its log (the error)
};

struct JobStatus {
  std::vector<ShardStatus> shards;
  std::optional<std::string> join_state;  // the join job as Slurm reports it, when it knows it
  bool join_never_runs = false;           // pending on shards that failed (JobInfo::never_runs)
  bool output_written = false;            // the output exists (filter: joined)
};

// How the job in plan.folder stands: done markers, the queue, the logs.
JobStatus job_status(const FarmPlan& plan);

// Waits (polling squeue/scontrol every `poll_seconds`) until job `id` has ended, or pends on a
// dependency that can never be met (JobInfo::never_runs: state PENDING); how it ended, or nothing
// when Slurm forgot it before it was seen ending. A stop request through `cancel`
// ends the wait (Error{interrupted}) within a quarter of a second; the job itself goes on.
struct JobEnd {
  std::string state;
  int exit_code = 0;
  std::string reason;
};
std::optional<JobEnd> wait_for_job(const std::string& id, double poll_seconds = 1.0,
                                   CancelToken cancel = {});

// A job folder's path from the output: OUTPUT.farm; for a pattern tex_%04d.png, tex_.farm.
std::filesystem::path job_folder_for(const std::string& output);

}  // namespace ifsfx::farm
