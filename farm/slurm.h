// SPDX-License-Identifier: Apache-2.0
// The Slurm commands a farm job needs, run as processes: sbatch to submit, squeue and scontrol to
// ask how jobs stand. Nothing here prints; failures throw ifsfx::Error naming the command.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ifsfx::farm {

struct ProcessResult {
  int exit_code = 0;  // 128 + N when killed by signal N
  std::string out;    // stdout
  std::string err;    // stderr
};

// Runs argv[0] (looked up on PATH) with the arguments, waits, and collects its output. Throws
// Error{not_found} when the program does not exist ("sbatch: not found; is Slurm installed?").
ProcessResult run_process(const std::vector<std::string>& argv);

// `sbatch --parsable ARGS...`: the job id. Throws Error{io} with sbatch's own message on failure.
std::string sbatch(const std::vector<std::string>& args);

// `scancel ID`. Throws Error{io} with scancel's own message when it fails.
void scancel(const std::string& id);

// The array tasks of job `id` still in the queue (pending, running, completing): task → state.
std::map<int, std::string> queued_array_tasks(const std::string& id);

struct JobInfo {
  std::string state;   // COMPLETED, FAILED, CANCELLED, PENDING, RUNNING, ...
  int exit_code = 0;   // the job's exit status (ExitCode=N:S: N, or 128 + S when killed)
  std::string reason;  // why it waits or ended (Dependency, DependencyNeverSatisfied, ...)
  bool finished() const;
  // Pending on a dependency that can no longer be met (a job it waits on failed): it will never
  // start, and stays in the queue until cancelled where the cluster does not end such jobs.
  bool never_runs() const;
};

// What `scontrol show job ID` says; nothing when Slurm no longer knows the job (its record is
// purged MinJobAge seconds after it ended). For an array job, how the array as a whole stands.
std::optional<JobInfo> job_info(const std::string& id);

// job_info's reading of `scontrol -o show job ID`'s output: one line per job, and for an array
// one per task (or range of pending tasks), in no order to rely on -- the first line is the
// array's own record, which is its last task. So the array has ended only when every line has:
// an unfinished line's state while one runs or waits; else the first line that did not
// COMPLETE (FAILED, CANCELLED, ... with its exit code); else COMPLETED.
JobInfo job_info_of(const std::string& scontrol_lines);

}  // namespace ifsfx::farm
