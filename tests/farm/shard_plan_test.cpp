// SPDX-License-Identifier: Apache-2.0
#include "farm/shard_plan.h"

#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

#include "farm/farm_job.h"
#include "ifs/error.h"

namespace ifsfx::farm {
namespace {

std::filesystem::path temp_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("ifsfx-farm-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(split_frames, cuts_into_consecutive_spans_differing_by_at_most_one) {
  const std::vector<FrameSpan> spans = split_frames({10, 19}, 3);
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans[0].first, 10);
  EXPECT_EQ(spans[0].last, 13);
  EXPECT_EQ(spans[1].first, 14);
  EXPECT_EQ(spans[1].last, 16);
  EXPECT_EQ(spans[2].first, 17);
  EXPECT_EQ(spans[2].last, 19);
}

TEST(split_frames, one_frame_per_shard_at_most) {
  const std::vector<FrameSpan> spans = split_frames({0, 4}, 5);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    EXPECT_EQ(spans[i].first, static_cast<std::int64_t>(i));
    EXPECT_EQ(spans[i].last, static_cast<std::int64_t>(i));
  }
}

TEST(split_frames, refuses_no_shards_and_more_shards_than_frames) {
  try {
    split_frames({0, 9}, 0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(), "--shards: must be at least 1 (got 0)");
  }
  try {
    split_frames({0, 9}, 11);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--shards: more shards than frames (10 frames, got 11)");
  }
}

TEST(farm_plan, written_plan_reads_back_with_its_segments_in_the_outputs_container) {
  const auto dir = temp_folder("plan");
  FarmPlan plan;
  plan.folder = dir / "out.mp4.farm";
  plan.input = "/films/a film.mov";
  plan.output = "/films/out.mp4";
  plan.shards = split_frames({0, 99}, 4);
  write_plan(plan);
  const FarmPlan back = read_plan(plan.folder);
  EXPECT_EQ(back.kind, JobKind::filter);
  EXPECT_EQ(back.input, plan.input);
  EXPECT_EQ(back.output, plan.output);
  ASSERT_EQ(back.shards.size(), 4u);
  EXPECT_EQ(back.shards[3].first, 75);
  EXPECT_EQ(back.shards[3].last, 99);
  EXPECT_EQ(segment_file(back, 2), plan.folder / "segments" / "segment-0002.mp4");
  EXPECT_EQ(shards_done(back), std::vector<bool>(4, false));
  std::ofstream(done_marker(back.folder, 1)).put('\n');
  EXPECT_EQ(shards_done(back), (std::vector<bool>{false, true, false, false}));
  // A new plan in the folder forgets the old job's shards: no stale segment gets joined.
  std::ofstream(segment_file(back, 1)).put('\n');
  write_plan(plan);
  EXPECT_EQ(shards_done(read_plan(plan.folder)), std::vector<bool>(4, false));
  EXPECT_FALSE(std::filesystem::exists(segment_file(back, 1)));
}

TEST(farm_plan, bad_line_names_file_and_line) {
  const auto dir = temp_folder("bad_plan");
  std::ofstream(dir / "plan.txt") << "ifsfx-farm 1\nkind filter\nshard 9 3\n";
  try {
    read_plan(dir);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_EQ(std::string(e.what()),
              (dir / "plan.txt").string() + ":3: expected 'shard FIRST LAST' (got 'shard 9 3')");
  }
}

TEST(farm_plan, missing_plan_is_not_found) {
  const auto dir = temp_folder("no_plan");
  try {
    read_plan(dir);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
  }
}

TEST(farm_job, folder_sits_beside_the_output) {
  EXPECT_EQ(job_folder_for("/films/out.mp4"), "/films/out.mp4.farm");
  EXPECT_EQ(job_folder_for("/tex/t_%04d.png"), "/tex/t_.farm");
}

TEST(farm_job, scripts_run_each_shard_with_its_range_and_the_join_after) {
  const auto dir = temp_folder("scripts");
  FarmPlan plan;
  plan.folder = dir / "o'k.mkv.farm";
  plan.output = (dir / "o'k.mkv").string();
  plan.shards = split_frames({0, 9}, 2);
  write_plan(plan);
  SlurmOptions slurm{.partition = "gpu",
                     .time = "1:00:00",
                     .cpus_per_task = 4,
                     .mem = "2G",
                     .extra = {"--account=film"}};
  JobCommands commands;
  commands.shard = [&](std::size_t i) {
    return std::vector<std::string>{"/bin/ifsfx", "filter", "--frames",
                                    std::to_string(plan.shards[i].first)};
  };
  commands.join = {"/bin/ifsfx", "farm", "join", plan.folder.string()};
  write_scripts(plan, slurm, commands);
  std::ifstream in(plan.folder / "shards.sh");
  const std::string shards((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(shards.find("#SBATCH --array=0-1\n"), std::string::npos) << shards;
  EXPECT_NE(shards.find("#SBATCH --partition=gpu\n#SBATCH --time=1:00:00\n#SBATCH "
                        "--cpus-per-task=4\n#SBATCH --mem=2G\n#SBATCH --account=film\n"),
            std::string::npos)
      << shards;
  EXPECT_NE(shards.find("  1) '/bin/ifsfx' 'filter' '--frames' '5' ;;"), std::string::npos)
      << shards;
  std::ifstream join_in(plan.folder / "join.sh");
  const std::string join((std::istreambuf_iterator<char>(join_in)), {});
  // A quote in a path is kept intact for bash.
  EXPECT_NE(join.find("exec '/bin/ifsfx' 'farm' 'join' '" + dir.string() + "/o'\\''k.mkv.farm'"),
            std::string::npos)
      << join;
  std::ifstream submit_in(plan.folder / "submit.sh");
  const std::string submit((std::istreambuf_iterator<char>(submit_in)), {});
  EXPECT_NE(submit.find("--dependency=afterok:$array"), std::string::npos) << submit;
}

}  // namespace
}  // namespace ifsfx::farm
