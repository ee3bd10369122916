// SPDX-License-Identifier: Apache-2.0
#include "farm/slurm.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <sstream>

#include <fmt/format.h>

#include "ifs/error.h"

extern char** environ;

namespace ifsfx::farm {

namespace {

std::string joined(const std::vector<std::string>& argv) {
  std::string text;
  for (const auto& a : argv) {
    if (!text.empty()) text.push_back(' ');
    text.append(a);
  }
  return text;
}

// The value of `key=` in scontrol's one-line output ("JobState=FAILED Reason=..."), or "".
std::string field(const std::string& line, const std::string& key) {
  const std::string needle = " " + key + "=";
  const std::string padded = " " + line;
  const auto at = padded.find(needle);
  if (at == std::string::npos) return {};
  const auto start = at + needle.size();
  return padded.substr(start, padded.find(' ', start) - start);
}

// What a failed command said, for a message: its stderr (else stdout), trailing newlines gone.
std::string complaint(const ProcessResult& r) {
  std::string why = r.err.empty() ? r.out : r.err;
  while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
  return why;
}

JobInfo job_info_of_line(const std::string& line) {
  JobInfo info;
  info.state = field(line, "JobState");
  info.reason = field(line, "Reason");
  const std::string code = field(line, "ExitCode");  // "N:S"
  const auto colon = code.find(':');
  if (colon != std::string::npos) {
    const int status = std::atoi(code.substr(0, colon).c_str());
    const int signal = std::atoi(code.substr(colon + 1).c_str());
    info.exit_code = signal != 0 ? 128 + signal : status;
  }
  return info;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv) {
  std::array<int, 2> out{}, err{};
  if (pipe(out.data()) != 0 || pipe(err.data()) != 0)
    throw Error(ErrorKind::io, fmt::format("{}: cannot make a pipe", argv.at(0)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);
  for (int fd : {out[0], out[1], err[0], err[1]}) posix_spawn_file_actions_addclose(&actions, fd);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  close(err[1]);
  if (spawned != 0) {
    close(out[0]);
    close(err[0]);
    throw Error(spawned == ENOENT ? ErrorKind::not_found : ErrorKind::io,
                fmt::format("{}: cannot run ({}){}", argv[0], std::strerror(spawned),
                            spawned == ENOENT ? "; is Slurm installed and on PATH?" : ""));
  }
  ProcessResult result;
  std::array<pollfd, 2> fds{pollfd{out[0], POLLIN, 0}, pollfd{err[0], POLLIN, 0}};
  std::array<std::string*, 2> into{&result.out, &result.err};
  int open_fds = 2;
  while (open_fds > 0) {
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      char buffer[4096];
      const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        into[i]->append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string sbatch(const std::vector<std::string>& args) {
  std::vector<std::string> argv{"sbatch", "--parsable"};
  argv.insert(argv.end(), args.begin(), args.end());
  const ProcessResult r = run_process(argv);
  std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
  if (r.exit_code != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw Error(ErrorKind::io,
                fmt::format("{}: failed (exit {}): {}", joined(argv), r.exit_code, complaint(r)));
  }
  return id;
}

void scancel(const std::string& id) {
  const ProcessResult r = run_process({"scancel", id});
  if (r.exit_code == 0) return;
  throw Error(ErrorKind::io,
              fmt::format("scancel {}: failed (exit {}): {}", id, r.exit_code, complaint(r)));
}

std::map<int, std::string> queued_array_tasks(const std::string& id) {
  const ProcessResult r = run_process({"squeue", "-h", "-r", "-j", id, "-o", "%i %T"});
  std::map<int, std::string> tasks;
  if (r.exit_code != 0) return tasks;  // an id Slurm no longer knows: nothing queued
  std::istringstream lines(r.out);
  std::string job, state;
  const std::string prefix = id + "_";  // "123_4": task 4 of array job 123
  while (lines >> job >> state) {
    if (!job.starts_with(prefix)) continue;
    const std::string task = job.substr(prefix.size());
    if (!task.empty() && task.find_first_not_of("0123456789") == std::string::npos)
      tasks[std::stoi(task)] = state;
  }
  return tasks;
}

bool JobInfo::finished() const {
  return !(state == "PENDING" || state == "RUNNING" || state == "CONFIGURING" ||
           state == "COMPLETING" || state == "SUSPENDED" || state == "REQUEUED" ||
           state == "RESIZING" || state.empty());
}

bool JobInfo::never_runs() const {
  return state == "PENDING" && reason == "DependencyNeverSatisfied";
}

JobInfo job_info_of(const std::string& scontrol_lines) {
  std::vector<JobInfo> lines;
  std::istringstream in(scontrol_lines);
  for (std::string line; std::getline(in, line);)
    if (line.find("JobState=") != std::string::npos) lines.push_back(job_info_of_line(line));
  if (lines.empty()) return {};
  // A task still running or waiting for its turn decides; one that can never start only when
  // nothing else is still going.
  for (const JobInfo& l : lines)
    if (!l.finished() && !l.never_runs()) return l;
  for (const JobInfo& l : lines)
    if (l.never_runs()) return l;
  for (const JobInfo& l : lines)
    if (l.state != "COMPLETED") return l;
  return lines.front();
}

std::optional<JobInfo> job_info(const std::string& id) {
  const ProcessResult r = run_process({"scontrol", "-o", "show", "job", id});
  if (r.exit_code != 0) return std::nullopt;
  return job_info_of(r.out);
}

}  // namespace ifsfx::farm
