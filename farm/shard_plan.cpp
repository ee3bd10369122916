// SPDX-License-Identifier: Apache-2.0
#include "farm/shard_plan.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::farm {

std::vector<FrameSpan> split_frames(FrameSpan span, int shards) {
  if (shards < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--shards: must be at least 1 (got {})", shards));
  if (span.size() < shards)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--shards: more shards than frames ({} frames, got {})",
                            std::max<std::int64_t>(0, span.size()), shards));
  std::vector<FrameSpan> out;
  const std::int64_t base = span.size() / shards;
  const std::int64_t extra = span.size() % shards;
  std::int64_t first = span.first;
  for (int i = 0; i < shards; ++i) {
    const std::int64_t n = base + (i < extra ? 1 : 0);
    out.push_back({first, first + n - 1});
    first += n;
  }
  return out;
}

std::filesystem::path plan_file(const std::filesystem::path& folder) {
  return folder / "plan.txt";
}

std::filesystem::path segment_file(const FarmPlan& plan, std::size_t shard) {
  return plan.folder / "segments" /
         fmt::format("segment-{:04d}{}", shard,
                     std::filesystem::path(plan.output).extension().string());
}

std::filesystem::path done_marker(const std::filesystem::path& folder, std::size_t shard) {
  return folder / "done" / fmt::format("shard-{:04d}", shard);
}

std::filesystem::path shard_log(const std::filesystem::path& folder, std::size_t shard) {
  return folder / "logs" / fmt::format("shard-{:04d}.log", shard);
}

std::filesystem::path join_log(const std::filesystem::path& folder) {
  return folder / "logs" / "join.log";
}

void write_plan(const FarmPlan& plan) {
  std::error_code ec;
  // A new plan starts clean: an earlier job's done markers, segments and logs would be taken for
  // this one's (a stale segment joined into the output).
  for (const char* stale : {"logs", "segments", "done", "jobs.txt"})
    std::filesystem::remove_all(plan.folder / stale, ec);
  for (const char* sub : {"logs", "segments", "done"}) {
    std::filesystem::create_directories(plan.folder / sub, ec);
    if (ec)
      throw Error(ErrorKind::io, fmt::format("{}: cannot create ({})", (plan.folder / sub).string(),
                                             ec.message()));
  }
  const auto path = plan_file(plan.folder);
  std::ofstream out(path);
  out << "ifsfx-farm 1\n"
      << "kind " << (plan.kind == JobKind::filter ? "filter" : "texture") << '\n'
      << "input " << plan.input << '\n'
      << "output " << plan.output << '\n';
  for (const FrameSpan& s : plan.shards) out << "shard " << s.first << ' ' << s.last << '\n';
  out.close();
  if (!out) throw Error(ErrorKind::io, fmt::format("{}: cannot write", path.string()));
}

FarmPlan read_plan(const std::filesystem::path& folder) {
  const auto path = plan_file(folder);
  std::ifstream in(path);
  if (!in)
    throw Error(ErrorKind::not_found,
                fmt::format("{}: no farm job here (written by `ifsfx farm filter|texture`)",
                            path.string()));
  FarmPlan plan;
  plan.folder = folder;
  std::string line;
  int number = 0;
  bool header = false;
  const auto bad = [&](const std::string& why) {
    return Error(ErrorKind::parse,
                 fmt::format("{}:{}: {} (got '{}')", path.string(), number, why, line));
  };
  while (std::getline(in, line)) {
    ++number;
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space);
    const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
    if (key == "ifsfx-farm") {
      if (value != "1") throw bad("unknown plan version");
      header = true;
    } else if (key == "kind") {
      if (value != "filter" && value != "texture") throw bad("kind must be filter or texture");
      plan.kind = value == "filter" ? JobKind::filter : JobKind::texture;
    } else if (key == "input") {
      plan.input = value;
    } else if (key == "output") {
      plan.output = value;
    } else if (key == "shard") {
      std::istringstream fields(value);
      FrameSpan s;
      if (!(fields >> s.first >> s.last) || s.first < 0 || s.last < s.first)
        throw bad("expected 'shard FIRST LAST'");
      plan.shards.push_back(s);
    } else if (!line.empty()) {
      throw bad("unknown key");
    }
  }
  if (!header || plan.shards.empty() || plan.output.empty())
    throw Error(
        ErrorKind::parse,
        fmt::format("{}: incomplete plan (header, output and shards needed)", path.string()));
  return plan;
}

std::vector<bool> shards_done(const FarmPlan& plan) {
  std::vector<bool> done;
  std::error_code ec;
  for (std::size_t i = 0; i < plan.shards.size(); ++i)
    done.push_back(std::filesystem::exists(done_marker(plan.folder, i), ec));
  return done;
}

}  // namespace ifsfx::farm
