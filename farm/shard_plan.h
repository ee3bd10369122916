// SPDX-License-Identifier: Apache-2.0
// The plan of a farm job: which frames each shard makes, and the folder that holds the job
// (OUTPUT.farm/: plan.txt, the batch scripts, logs/, segments/, done/, jobs.txt).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ifsfx::farm {

// Frames first..last, both included, counted from 0 as `ifsfx filter --frames` counts them.
struct FrameSpan {
  std::int64_t first = 0;
  std::int64_t last = 0;
  std::int64_t size() const { return last - first + 1; }
};

// `span` cut into `shards` consecutive spans whose sizes differ by at most one (the first ones
// the larger). Throws Error{invalid_argument} naming --shards when shards < 1 or more shards
// than frames.
std::vector<FrameSpan> split_frames(FrameSpan span, int shards);

enum class JobKind { filter, texture };

struct FarmPlan {
  JobKind kind = JobKind::filter;
  std::filesystem::path folder;  // the job folder, absolute
  std::string input;             // filter: the input movie or sequence; texture: the superIFS
  std::string output;            // filter: the output movie; texture: the file pattern
  std::vector<FrameSpan> shards;
};

// Where each part of a job lives inside its folder.
std::filesystem::path plan_file(const std::filesystem::path& folder);
// A filter shard's segment, in the output's container (whose muxer keeps the decode times a
// stream-copy join needs): segments/segment-0003.mp4.
std::filesystem::path segment_file(const FarmPlan& plan, std::size_t shard);
std::filesystem::path done_marker(const std::filesystem::path& folder, std::size_t shard);
std::filesystem::path shard_log(const std::filesystem::path& folder, std::size_t shard);
std::filesystem::path join_log(const std::filesystem::path& folder);

// Writes plan.txt (one "key value" line each; a shard as "shard FIRST LAST") and creates the
// folder's subfolders, removing what an earlier job in the folder left (done markers, segments,
// logs, job ids). Throws Error{io} naming the file.
void write_plan(const FarmPlan& plan);
// Reads `folder`/plan.txt. Throws Error{not_found} when it is missing, Error{parse} naming the
// file and line for anything else.
FarmPlan read_plan(const std::filesystem::path& folder);

// The shards whose done marker exists (written by the shard's script after it succeeded).
std::vector<bool> shards_done(const FarmPlan& plan);

}  // namespace ifsfx::farm
