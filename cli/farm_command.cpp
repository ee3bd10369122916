// SPDX-License-Identifier: Apache-2.0
// `ifsfx farm filter|texture|status|resume`: a long movie or texture sequence sharded over a Slurm
// cluster. The job folder (OUTPUT.farm/) holds the plan, one array job of shards (each an ordinary
// `ifsfx filter --frames A:B` or `ifsfx texture --frame-range A:B`) and, for a movie, a join job
// that runs once every shard succeeded and concatenates the segments by stream copy.
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "cli/option_groups.h"
#include "cli/stop_signals.h"
#include "engine/fractal_engine.h"
#include "farm/farm_job.h"
#include "farm/segment_join.h"
#include "farm/shard_plan.h"
#include "farm/slurm.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "run/filter_options.h"
#include "run/texture_options.h"
#include "superifs/superifs_file.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;
using farm::FarmPlan;
using farm::JobKind;

constexpr const char* shared_paths_note =
    "Every path (input, output, the job folder, the ifsfx binary) must be on a filesystem that "
    "all nodes of the cluster see under the same name: give absolute paths.";

struct FarmArgs {
  std::string input;
  std::string output;
  std::string frames;  // filter: START:END of the input; texture: the sequence's length
  int shards = 0;
  bool submit = false;
  bool wait = false;
  farm::SlurmOptions slurm;
};

void add_slurm_options(CLI::App& cmd, FarmArgs& args) {
  cmd.add_option("--shards", args.shards, "K, the number of array tasks the frames are cut into")
      ->required();
  cmd.add_flag("--submit", args.submit,
               "Submit with sbatch and print the job ids (without it, the scripts are only "
               "written: submit.sh submits them)");
  cmd.add_flag("--wait", args.wait,
               "With --submit: wait for the job to end; the exit status is the join's (texture: "
               "the shards')");
  cmd.add_option("--partition", args.slurm.partition, "sbatch --partition")->group("Slurm");
  cmd.add_option("--time", args.slurm.time, "sbatch --time: the limit per task, e.g. 2:00:00")
      ->group("Slurm");
  cmd.add_option("--cpus-per-task", args.slurm.cpus_per_task,
                 "sbatch --cpus-per-task; the shards then use as many threads")
      ->check(CLI::Range(1, 4096))
      ->group("Slurm");
  cmd.add_option("--mem", args.slurm.mem, "sbatch --mem per task, e.g. 8G")->group("Slurm");
  cmd.add_option("--sbatch-arg", args.slurm.extra,
                 "One more sbatch argument, handed on unchanged (repeatable), e.g. "
                 "--sbatch-arg=--account=film")
      ->allow_extra_args(false)
      ->group("Slurm");
}

fs::path self_binary() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error(ErrorKind::io, "farm: cannot find the path of the ifsfx binary");
  return self;
}

void require_absolute(const std::string& path, const std::string& what) {
  if (!fs::path(path).is_absolute())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: must be an absolute path on a filesystem all nodes see (got {})",
                            what, path));
}

// Which options of `cmd` the user gave: what is not farm's own, to hand on to every shard.
std::vector<std::string> handed_on(const CLI::App& cmd) {
  return cmd.remaining();
}

// The options handed on to every shard, parsed as the shard's command (`ifsfx filter` or `ifsfx
// texture`) will parse them: bad ones fail here, before anything is submitted.
template <class Args, class AddOptions>
Args parse_handed_on(const std::vector<std::string>& tokens, const std::string& command,
                     AddOptions add_options) {
  auto args = std::make_shared<Args>();
  CLI::App parser{"ifsfx " + command};
  add_options(parser, args);
  std::vector<std::string> reversed(tokens.rbegin(), tokens.rend());
  try {
    parser.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw Error(ErrorKind::invalid_argument, fmt::format("farm {}: {}", command, e.what()));
  }
  return *args;
}

FilterArgs parse_filter_options(const std::vector<std::string>& tokens) {
  return parse_handed_on<FilterArgs>(tokens, "filter", [](CLI::App& parser, const auto& args) {
    add_filter_options(parser, args);
    parser.add_flag("-q,--quiet", args->quiet);
  });
}

bool given(const std::vector<std::string>& tokens, const std::string& name) {
  for (const auto& t : tokens)
    if (t == name || t.starts_with(name + "=")) return true;
  return false;
}

void submit_and_report(const FarmPlan& plan, const FarmArgs& args, bool with_join,
                       const std::vector<std::size_t>& shards);

std::vector<std::size_t> all_shards(const FarmPlan& plan) {
  std::vector<std::size_t> all(plan.shards.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

// --codec X and --fps-mode X come as two tokens: drop the value with its option.
std::vector<std::string> without_options(const std::vector<std::string>& tokens,
                                         const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    bool drop = false;
    for (const auto& n : names) {
      if (tokens[i] == n) {
        drop = true;
        ++i;  // its value
      } else if (tokens[i].starts_with(n + "=")) {
        drop = true;
      }
    }
    if (!drop) out.push_back(tokens[i]);
  }
  return out;
}

// The job folder's plan for frames `span` of the input cut into args.shards, written.
FarmPlan write_new_plan(JobKind kind, const FarmArgs& args, farm::FrameSpan span) {
  FarmPlan plan;
  plan.kind = kind;
  plan.folder = farm::job_folder_for(args.output);
  plan.input = args.input;
  plan.output = args.output;
  plan.shards = farm::split_frames(span, args.shards);
  farm::write_plan(plan);
  return plan;
}

void run_farm_filter(const FarmArgs& args, const std::vector<std::string>& extra) {
  require_absolute(args.output, "-o");
  require_absolute(args.input, "INPUT");
  if (video::is_sequence_pattern(args.output))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("-o: farm filter writes one movie, joined from the shards (got the "
                            "image sequence {}; use `ifsfx filter` per range for images)",
                            args.output));
  if (given(extra, "--preview") || given(extra, "--segment") || given(extra, "-o") ||
      given(extra, "--output"))
    throw Error(ErrorKind::invalid_argument,
                "farm filter: --preview, --segment and a second -o are not for farm jobs");
  const FilterArgs filter = parse_filter_options(extra);
  check_filter_rules(filter);
  StopSignals signals;  // Ctrl-C and SIGTERM: the checks and the count stop, nothing is submitted
  // The output policy, checked before anything is planned (the join applies it again).
  OutputOptions policy{.cancel = StopSignals::token()};
  policy.inputs.add(args.input);
  check_output(args.output, policy);
  // The output's encoder and frame timing, settled here so that every segment is encoded alike
  // (in Matroska) and the join can copy them into the output's container.
  const std::string encoder = video::resolve_encoder(args.output, filter.codec);
  const video::FrameTiming timing = video::resolve_timing(args.output, filter.codec, filter.timing);
  engine::FractalSettings settings = filter.fractal.settings();
  settings.animate = filter.animate;
  settings.superifs = filter.superifs;
  settings.buffers = filter.buffers;
  engine::FractalEngine check(settings);  // a bad preset or superIFS fails here

  video::silence_libav_log();
  std::int64_t frames = 0;
  if (video::is_sequence_pattern(args.input)) {
    frames =
        video::ImageSequenceSource(args.input, {.fps = filter.fps, .skip_gaps = filter.skip_gaps})
            .frame_count();
  } else {
    frames = video::FileSource(args.input).count_frames();
  }
  video::FrameRange range =
      args.frames.empty() ? video::FrameRange{} : video::parse_frame_range(args.frames);
  const std::int64_t last = range.last < 0 ? frames - 1 : std::min(range.last, frames - 1);
  policy.cancel.check("farm filter");
  const FarmPlan plan = write_new_plan(JobKind::filter, args, {range.first, last});

  const std::string self = self_binary().string();
  farm::JobCommands commands;
  commands.shard = [&](std::size_t i) {
    const farm::FrameSpan span = plan.shards[i];
    std::vector<std::string> argv{self,
                                  "filter",
                                  args.input,
                                  "-o",
                                  farm::segment_file(plan, i).string(),
                                  "--frames",
                                  fmt::format("{}:{}", span.first, span.last),
                                  "--segment",
                                  "--codec",
                                  encoder,
                                  "--fps-mode",
                                  timing == video::FrameTiming::constant ? "cfr" : "vfr"};
    for (const auto& t : without_options(extra, {"--codec", "--fps-mode"})) argv.push_back(t);
    if (args.slurm.cpus_per_task > 0 && !given(extra, "--threads"))
      argv.insert(argv.end(), {"--threads", std::to_string(args.slurm.cpus_per_task)});
    return argv;
  };
  commands.join = {self, "farm", "join", plan.folder.string()};
  farm::write_scripts(plan, args.slurm, commands);
  submit_and_report(plan, args, true, all_shards(plan));
}

void run_farm_texture(const FarmArgs& args, const std::vector<std::string>& extra) {
  require_absolute(args.output, "-o");
  if (given(extra, "--frame-range"))
    throw Error(ErrorKind::invalid_argument, "farm texture: --frame-range is set per shard");
  // The whole text a number, as `texture --frames` will read it in every shard ("7x" fails there).
  int frames = 0;
  const char* end = args.frames.data() + args.frames.size();
  if (std::from_chars(args.frames.data(), end, frames).ptr != end) frames = 0;
  if (frames < 1)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("--frames: the number of textures, at least 1 (got '{}')", args.frames));
  if (!video::is_sequence_pattern(args.output))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("-o: a numbered pattern like /abs/tex_%04d.png (got {}){}", args.output,
                            video::is_movie_name(args.output)
                                ? "; the shards write frames: make the movie from them, or run "
                                  "`ifsfx texture -o MOVIE` on one machine"
                                : ""));
  // A superIFS named by path must be seen by the nodes too; a shipped name is found anywhere.
  if (args.input.find('/') != std::string::npos) require_absolute(args.input, "SUPERPRESET");
  load_superifs(args.input);  // a bad one fails here
  // The texture options every shard gets, checked as `ifsfx texture` checks them.
  TextureArgs texture = parse_handed_on<TextureArgs>(extra, "texture", add_texture_options);
  texture.preset = args.input;
  texture.output = args.output;
  texture.frames = frames;
  check_texture_args(texture);
  StopSignals signals;
  OutputOptions policy{.cancel = StopSignals::token()};
  add_preset_input(policy.inputs, args.input);
  if (!texture.source.empty()) {
    require_absolute(texture.source, "--source");
    (void)read_image(texture.source);  // a missing or damaged source fails here, not per shard
    policy.inputs.add(texture.source);
  }
  // A writer for the pattern's extension that holds --bits, and the output policy.
  check_writable_image(video::sequence_path(args.output, 1), policy, texture.bits);
  policy.cancel.check("farm texture");

  const FarmPlan plan = write_new_plan(JobKind::texture, args, {0, frames - 1});
  const std::string self = self_binary().string();
  farm::JobCommands commands;
  commands.shard = [&](std::size_t i) {
    const farm::FrameSpan span = plan.shards[i];
    std::vector<std::string> argv{
        self,        "texture",       args.input,
        "-o",        args.output,     "--frames",
        args.frames, "--frame-range", fmt::format("{}:{}", span.first, span.last)};
    argv.insert(argv.end(), extra.begin(), extra.end());
    if (args.slurm.cpus_per_task > 0 && !given(extra, "--threads"))
      argv.insert(argv.end(), {"--threads", std::to_string(args.slurm.cpus_per_task)});
    return argv;
  };
  farm::write_scripts(plan, args.slurm, commands);
  submit_and_report(plan, args, false, all_shards(plan));
}

// Waits for the job's last step and says how it ended: 0 when it succeeded; otherwise an error
// naming the shards that failed and their logs.
void wait_and_report(const FarmPlan& plan, const farm::Submission& ids) {
  const std::string last = ids.join.empty() ? ids.array : ids.join;
  std::optional<farm::JobEnd> end;
  try {
    end = farm::wait_for_job(last, 1.0, StopSignals::token());
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::interrupted) throw;
    throw Error(ErrorKind::interrupted,
                fmt::format("farm: stopped waiting; the job goes on in Slurm (`ifsfx farm status "
                            "{}`; scancel {}{}{} cancels it)",
                            plan.folder.string(), ids.array,
                            ids.array.empty() || ids.join.empty() ? "" : " ", ids.join));
  }
  // A join that can never start would stay in the queue, and block `farm resume`: it goes.
  if (end && end->state == "PENDING" && !ids.join.empty()) farm::scancel(ids.join);
  const farm::JobStatus status = farm::job_status(plan);
  std::string failed;
  for (std::size_t i = 0; i < status.shards.size(); ++i)
    if (status.shards[i].state != farm::ShardState::done)
      failed += fmt::format("{}shard {} ({})", failed.empty() ? "" : ", ", i,
                            farm::shard_log(plan.folder, i).string());
  const bool ok =
      plan.kind == JobKind::filter
          ? (end ? end->state == "COMPLETED" && status.output_written : status.output_written)
          : failed.empty();
  if (ok) {
    fmt::print("farm: done -> {}\n", plan.output);
    return;
  }
  if (!failed.empty())
    throw Error(ErrorKind::io,
                fmt::format("farm: {} failed; {}; `ifsfx farm status {}` says more, `ifsfx farm "
                            "resume {}` finishes the job",
                            failed,
                            plan.kind == JobKind::filter ? "the join did not run, no output"
                                                         : "some files are missing",
                            plan.folder.string(), plan.folder.string()));
  // Every shard left its frames, yet Slurm may still count one of their tasks as not having
  // succeeded: a task cancelled just as it finished (scancel of a task already COMPLETED does
  // this too) makes the join's afterok unsatisfiable, and kill_invalid_depend cancels the join
  // before it starts. Its log (if any) is an older run's, so it is not the place to look.
  if (end && end->reason == "DependencyNeverSatisfied")
    throw Error(ErrorKind::io,
                fmt::format("farm: every shard's frames are done, but the join {} was cancelled "
                            "before it ran ({}: Slurm counts a task of job {} as cancelled or "
                            "failed, e.g. one cancelled as it finished); no output; `ifsfx farm "
                            "resume {}` runs the join",
                            ids.join, end->reason, ids.array, plan.folder.string()));
  throw Error(ErrorKind::io, fmt::format("farm: the join {} ({}, exit {}); see {}", ids.join,
                                         end ? end->state : "gone", end ? end->exit_code : -1,
                                         farm::join_log(plan.folder).string()));
}

void submit_and_report(const FarmPlan& plan, const FarmArgs& args, bool with_join,
                       const std::vector<std::size_t>& shards) {
  if (!args.submit) {
    if (args.wait) throw Error(ErrorKind::invalid_argument, "--wait: needs --submit");
    fmt::print("farm: {} shards planned in {}; submit with {}/submit.sh or --submit\n",
               plan.shards.size(), plan.folder.string(), plan.folder.string());
    return;
  }
  const farm::Submission ids = farm::submit(plan, shards, with_join);
  fmt::print("farm: submitted shards {}{}{}\n", ids.array.empty() ? "(none)" : ids.array,
             ids.join.empty() ? "" : ", join ", ids.join);
  std::fflush(stdout);
  if (args.wait) wait_and_report(plan, ids);
}

void run_status(const fs::path& folder) {
  const FarmPlan plan = farm::read_plan(fs::absolute(folder));
  const farm::JobStatus status = farm::job_status(plan);
  int done = 0, queued = 0, failed = 0, not_run = 0;
  for (std::size_t i = 0; i < status.shards.size(); ++i) {
    const farm::ShardStatus& s = status.shards[i];
    const farm::FrameSpan span = plan.shards[i];
    std::string what;
    switch (s.state) {
      case farm::ShardState::done:
        ++done;
        what = "done";
        break;
      case farm::ShardState::queued:
        ++queued;
        what = fmt::format("{}", s.queue_state == "PENDING" ? "pending" : "running");
        break;
      case farm::ShardState::failed:
        ++failed;
        what = fmt::format("failed, see {}: {}", farm::shard_log(plan.folder, i).string(),
                           s.last_line);
        break;
      case farm::ShardState::not_run:
        ++not_run;
        what = "not run";
        break;
    }
    fmt::print("shard {} frames {}-{}: {}\n", i, span.first, span.last, what);
  }
  std::string join;
  if (plan.kind == JobKind::filter)
    join = fmt::format("; join {}; output {}",
                       status.join_never_runs
                           ? "PENDING, never to run (`ifsfx farm resume` cancels it)"
                           : status.join_state.value_or("not known to Slurm"),
                       status.output_written ? "written" : "not written");
  fmt::print("{} shards: {} done, {} running or pending, {} failed, {} not run{}\n",
             status.shards.size(), done, queued, failed, not_run, join);
}

void run_resume(const fs::path& folder, const FarmArgs& args) {
  StopSignals signals;  // for --wait
  const FarmPlan plan = farm::read_plan(fs::absolute(folder));
  const farm::JobStatus status = farm::job_status(plan);
  std::vector<std::size_t> missing;
  for (std::size_t i = 0; i < status.shards.size(); ++i) {
    if (status.shards[i].state == farm::ShardState::queued)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("farm resume: shard {} is still {} in Slurm; wait or scancel it", i,
                              status.shards[i].queue_state));
    if (status.shards[i].state != farm::ShardState::done) missing.push_back(i);
  }
  if (status.join_never_runs)
    farm::scancel(farm::read_submission(plan)->join);  // its shards failed: it would pend for ever
  else if (plan.kind == JobKind::filter && status.join_state &&
           (*status.join_state == "PENDING" || *status.join_state == "RUNNING"))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("farm resume: the join is still {}", *status.join_state));
  if (plan.kind == JobKind::texture && missing.empty()) {
    std::printf("farm: every shard is done; nothing to resume\n");
    return;
  }
  FarmArgs submit = args;
  submit.submit = true;
  fmt::print("farm: resubmitting {} of {} shards\n", missing.size(), plan.shards.size());
  submit_and_report(plan, submit, plan.kind == JobKind::filter, missing);
}

void run_join(const fs::path& folder) {
  const FarmPlan plan = farm::read_plan(fs::absolute(folder));
  const std::vector<bool> done = farm::shards_done(plan);
  farm::JoinOptions options;
  for (std::size_t i = 0; i < plan.shards.size(); ++i) {
    if (!done[i])
      throw Error(ErrorKind::io, fmt::format("farm join: shard {} is not done (see {})", i,
                                             farm::shard_log(plan.folder, i).string()));
    options.segments.push_back(farm::segment_file(plan, i));
  }
  options.output = plan.output;
  StopSignals
      signals;  // scancel sends SIGTERM: the temporary file is removed, OUTPUT kept as it was
  options.policy.cancel = StopSignals::token();
  options.policy.inputs.add(plan.input);
  video::silence_libav_log();
  // The audio a single run would carry: a movie input's, placed by its clock.
  if (!video::is_sequence_pattern(plan.input)) {
    const video::FileSource input(plan.input);
    if (input.has_audio()) {
      options.audio_from = plan.input;
      options.audio_origin = input.start_time();
    }
  }
  const farm::JoinResult r = farm::join_segments(options);
  fmt::print("farm join: {} segments, {} packets, {:.2f} s, {:.1f} MB -> {}\n",
             options.segments.size(), r.video_packets, r.seconds, r.bytes / 1e6, plan.output);
}

}  // namespace

void add_farm_command(CLI::App& app) {
  auto* farm = app.add_subcommand(
      "farm", fmt::format("Shard a movie filter or a texture sequence over a Slurm cluster. {}",
                          shared_paths_note));
  farm->require_subcommand(1);

  auto filter_args = std::make_shared<FarmArgs>();
  auto* filter = farm->add_subcommand(
      "filter",
      fmt::format("`ifsfx filter INPUT -o OUTPUT` as K Slurm array tasks of consecutive frames "
                  "and a join job (afterok) that concatenates their segments by stream copy, "
                  "with the input's audio, into OUTPUT. The job folder is OUTPUT.farm/. Every "
                  "other option is `ifsfx filter`'s, handed on to each shard (same settings and "
                  "seed: the frames equal one run's; `ifsfx filter --help` lists them). {}",
                  shared_paths_note));
  filter->add_option("input", filter_args->input, "Input movie or image sequence (absolute)")
      ->required();
  filter->add_option("-o,--output", filter_args->output, "Output movie (absolute)")->required();
  filter->add_option("--frames", filter_args->frames,
                     "Source frames START:END to filter (as `ifsfx filter --frames`)");
  add_slurm_options(*filter, *filter_args);
  filter->allow_extras();
  filter->callback([filter, filter_args] { run_farm_filter(*filter_args, handed_on(*filter)); });

  auto texture_args = std::make_shared<FarmArgs>();
  auto* texture = farm->add_subcommand(
      "texture",
      fmt::format("`ifsfx texture SUPERPRESET --frames N -o tex_%04d.png` as K Slurm array tasks "
                  "of consecutive frames: the same files. The job folder is tex_.farm/. Every "
                  "other option is `ifsfx texture`'s. {}",
                  shared_paths_note));
  texture->add_option("superpreset", texture_args->input, "SuperIFS: shipped name or path")
      ->required();
  texture->add_option("-o,--output", texture_args->output, "Output pattern (absolute)")->required();
  texture->add_option("--frames", texture_args->frames, "N, the number of textures")->required();
  add_slurm_options(*texture, *texture_args);
  texture->allow_extras();
  texture->callback(
      [texture, texture_args] { run_farm_texture(*texture_args, handed_on(*texture)); });

  auto folder = std::make_shared<std::string>();
  auto* status = farm->add_subcommand(
      "status", "How a farm job stands: shards done, running, failed (with the log to read)");
  status->add_option("dir", *folder, "The job folder (OUTPUT.farm)")->required();
  status->callback([folder] { run_status(*folder); });

  auto resume_args = std::make_shared<FarmArgs>();
  auto* resume = farm->add_subcommand(
      "resume", "Submit again only the shards that are not done, and the join");
  resume->add_option("dir", *folder, "The job folder (OUTPUT.farm)")->required();
  resume->add_flag("--wait", resume_args->wait, "Wait for the job to end, as farm filter --wait");
  resume->callback([folder, resume_args] { run_resume(*folder, *resume_args); });

  auto* join = farm->add_subcommand("join", "The join job of a farm filter (run by join.sh)");
  join->add_option("dir", *folder, "The job folder")->required();
  join->group("");
  join->callback([folder] { run_join(*folder); });
}

}  // namespace ifsfx::app
