// SPDX-License-Identifier: Apache-2.0
#include "farm/farm_job.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "farm/slurm.h"
#include "ifs/error.h"

namespace ifsfx::farm {

namespace {

// One word for bash, single-quoted: 'it'\''s'.
std::string quoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) {
    if (c == '\'')
      out.append("'\\''");
    else
      out.push_back(c);
  }
  out.push_back('\'');
  return out;
}

std::string command_line(const std::vector<std::string>& argv) {
  std::string text;
  for (const auto& a : argv) {
    if (!text.empty()) text.push_back(' ');
    text.append(quoted(a));
  }
  return text;
}

// Slurm expands %-sequences in --output paths: a literal '%' is written "%%".
std::string slurm_path(const std::filesystem::path& path) {
  std::string out;
  for (char c : path.string()) {
    out.push_back(c);
    if (c == '%') out.push_back('%');
  }
  return out;
}

std::vector<std::string> sbatch_options(const SlurmOptions& o) {
  std::vector<std::string> args;
  if (!o.partition.empty()) args.push_back("--partition=" + o.partition);
  if (!o.time.empty()) args.push_back("--time=" + o.time);
  if (o.cpus_per_task > 0) args.push_back(fmt::format("--cpus-per-task={}", o.cpus_per_task));
  if (!o.mem.empty()) args.push_back("--mem=" + o.mem);
  args.insert(args.end(), o.extra.begin(), o.extra.end());
  return args;
}

std::filesystem::path script(const FarmPlan& plan, const char* name) {
  return plan.folder / name;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw Error(ErrorKind::io, fmt::format("{}: cannot write", path.string()));
  std::filesystem::permissions(
      path, std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec,
      std::filesystem::perm_options::add);
}

std::string last_line_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

std::filesystem::path jobs_file(const FarmPlan& plan) {
  return plan.folder / "jobs.txt";
}

}  // namespace

void write_scripts(const FarmPlan& plan, const SlurmOptions& options, const JobCommands& commands) {
  const std::size_t count = plan.shards.size();
  std::string sh = fmt::format(
      "#!/bin/bash\n"
      "# ifsfx farm: the shards of the job in {0}, one Slurm array task each.\n"
      "# Task i makes frames plan.txt gives it; a shard that succeeds leaves done/shard-NNNN.\n"
      "#SBATCH --job-name=ifsfx-shard\n"
      "#SBATCH --array=0-{1}\n"
      "#SBATCH --output={2}\n",
      plan.folder.string(), count - 1, slurm_path(plan.folder / "logs") + "/shard-%4a.log");
  for (const auto& a : sbatch_options(options)) sh += "#SBATCH " + a + "\n";
  sh += fmt::format(
      "set -u\n"
      "i=${{SLURM_ARRAY_TASK_ID:?run as a Slurm array task}}\n"
      "marker={}/done/shard-$(printf %04d \"$i\")\n"
      "rm -f \"$marker\"\n"
      "case $i in\n",
      quoted(plan.folder.string()));
  for (std::size_t i = 0; i < count; ++i)
    sh += fmt::format("  {}) {} ;;\n", i, command_line(commands.shard(i)));
  sh +=
      "  *) echo \"ifsfx farm: no shard $i in this job\" >&2; exit 2 ;;\n"
      "esac\n"
      "rc=$?\n"
      "[ $rc -eq 0 ] && touch \"$marker\"\n"
      "exit $rc\n";
  write_file(script(plan, "shards.sh"), sh);

  std::string submit_sh = fmt::format(
      "#!/bin/bash\n"
      "# Submits the job in {0} as `ifsfx farm ... --submit` does; ids go to jobs.txt.\n"
      "set -euo pipefail\n"
      "array=$(sbatch --parsable {1})\n"
      "array=${{array%%;*}}\n"
      "echo \"array $array\" > {2}\n",
      plan.folder.string(), quoted(script(plan, "shards.sh").string()),
      quoted(jobs_file(plan).string()));
  if (!commands.join.empty()) {
    std::string join = fmt::format(
        "#!/bin/bash\n"
        "# ifsfx farm: joins the segments of {} into the output, once every shard succeeded.\n"
        "#SBATCH --job-name=ifsfx-join\n"
        "#SBATCH --output={}\n"
        "# Once a shard has failed the join can never run: Slurm then ends it instead of leaving\n"
        "# it pending for ever (its default, unless the cluster sets kill_invalid_depend).\n"
        "#SBATCH --kill-on-invalid-dep=yes\n",
        plan.folder.string(), slurm_path(join_log(plan.folder)));
    for (const auto& a : sbatch_options(options))
      if (!a.starts_with("--cpus-per-task")) join += "#SBATCH " + a + "\n";
    join += "exec " + command_line(commands.join) + "\n";
    write_file(script(plan, "join.sh"), join);
    submit_sh += fmt::format(
        "join=$(sbatch --parsable --dependency=afterok:$array {})\n"
        "join=${{join%%;*}}\n"
        "echo \"join $join\" >> {}\n",
        quoted(script(plan, "join.sh").string()), quoted(jobs_file(plan).string()));
  }
  submit_sh += "cat " + quoted(jobs_file(plan).string()) + "\n";
  write_file(script(plan, "submit.sh"), submit_sh);
}

Submission submit(const FarmPlan& plan, const std::vector<std::size_t>& shards, bool with_join) {
  Submission ids;
  if (!shards.empty()) {
    std::string list;
    for (std::size_t i : shards) {
      if (!list.empty()) list.push_back(',');
      list.append(std::to_string(i));
    }
    std::vector<std::string> args;
    if (!list.empty()) args.push_back("--array=" + list);
    args.push_back(script(plan, "shards.sh").string());
    ids.array = sbatch(args);
  }
  if (with_join) {
    std::vector<std::string> args;
    if (!ids.array.empty()) args.push_back("--dependency=afterok:" + ids.array);
    args.push_back(script(plan, "join.sh").string());
    try {
      ids.join = sbatch(args);
    } catch (...) {
      if (!ids.array.empty()) run_process({"scancel", ids.array});
      throw;
    }
  }
  std::ofstream out(jobs_file(plan));
  if (!ids.array.empty()) out << "array " << ids.array << '\n';
  if (!ids.join.empty()) out << "join " << ids.join << '\n';
  out.close();
  if (!out) throw Error(ErrorKind::io, fmt::format("{}: cannot write", jobs_file(plan).string()));
  return ids;
}

std::optional<Submission> read_submission(const FarmPlan& plan) {
  std::ifstream in(jobs_file(plan));
  if (!in) return std::nullopt;
  Submission ids;
  std::string key, value;
  while (in >> key >> value) {
    if (key == "array") ids.array = value;
    if (key == "join") ids.join = value;
  }
  return ids;
}

JobStatus job_status(const FarmPlan& plan) {
  JobStatus status;
  const std::vector<bool> done = shards_done(plan);
  const std::optional<Submission> ids = read_submission(plan);
  std::map<int, std::string> queued;
  if (ids && !ids->array.empty()) queued = queued_array_tasks(ids->array);
  std::error_code ec;
  for (std::size_t i = 0; i < plan.shards.size(); ++i) {
    ShardStatus s;
    if (done[i]) {
      s.state = ShardState::done;
    } else if (const auto q = queued.find(static_cast<int>(i)); q != queued.end()) {
      s.state = ShardState::queued;
      s.queue_state = q->second;
    } else if (std::filesystem::exists(shard_log(plan.folder, i), ec)) {
      s.state = ShardState::failed;
      s.last_line = last_line_of(shard_log(plan.folder, i));
    }
    status.shards.push_back(s);
  }
  if (ids && !ids->join.empty())
    if (const auto info = job_info(ids->join)) {
      status.join_state = info->state;
      status.join_never_runs = info->never_runs();
    }
  status.output_written = std::filesystem::exists(plan.output, ec);
  return status;
}

std::optional<JobEnd> wait_for_job(const std::string& id, double poll_seconds, CancelToken cancel) {
  const std::string what = fmt::format("waiting for Slurm job {}", id);
  for (;;) {
    cancel.check(what.c_str());
    const std::optional<JobInfo> info = job_info(id);
    if (!info) return std::nullopt;
    if (info->finished() || info->never_runs())
      return JobEnd{info->state, info->exit_code, info->reason};
    // Slept in short slices, so that a stop request is seen soon.
    const auto until =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(poll_seconds);
    while (std::chrono::steady_clock::now() < until) {
      cancel.check(what.c_str());
      std::this_thread::sleep_for(std::min<std::chrono::duration<double>>(
          until - std::chrono::steady_clock::now(), std::chrono::milliseconds(250)));
    }
  }
}

std::filesystem::path job_folder_for(const std::string& output) {
  const auto percent = output.find('%');
  if (percent == std::string::npos) return output + ".farm";
  return output.substr(0, percent) + ".farm";
}

}  // namespace ifsfx::farm
