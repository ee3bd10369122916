// SPDX-License-Identifier: Apache-2.0
#include "studio/render_jobs.h"

#include "run/picture_options.h"

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "run/arguments.h"
#include "run/filter_run.h"
#include "run/texture_run.h"
#include "studio/fields.h"
#include "studio/render.h"
#include "studio/superifs.h"
#include "superifs/superifs_file.h"
#include "video/image_sequence.h"

namespace ifsfx::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The output's name in the folder, with one of `extensions`.
fs::path output_name(const json& body, const StudioContext& context,
                     const std::vector<std::string>& extensions) {
  const std::string name = required_text(body, "file");
  const std::string ext = lower_extension(name);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
    std::string list;
    for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a name ending in {} (got '{}')", list, name));
  }
  return folder_file(context.folder(), name, false);
}

int submit_still(JobQueue& jobs, const json& body, StudioContext& context) {
  StudioRender render = studio_render_from_json(
      body, [&](const std::string& name) { return context.source_path(name); });
  const fs::path target = output_name(body, context, {".png", ".tif", ".tiff", ".exr", ".jpg"});
  const int bits = static_cast<int>(integer_field(body, "bits", 8, 8, 16));
  // A flame is rendered at the file's depth, as `ifsfx render FILE.flame` renders it.
  render.flame_depth = lower_extension(target) == ".exr" ? CV_32F : bits == 16 ? CV_16U : CV_8U;
  OutputOptions policy{.inputs = context.inputs()};
  if (!render.source.empty()) policy.inputs.add(render.source);
  check_writable_image(target, policy, bits);
  JobSpec spec{.kind = "still", .title = target.filename().string(), .writes = {target.string()}};
  if (!render.source.empty()) spec.reads.push_back(render.source.string());
  return jobs.submit(std::move(spec), [=](JobContext& job) {
    job.progress(
        -1, "rendering",
        fmt::format("{} {}x{}", to_string(render.mode), render.size.width, render.size.height));
    const StudioImage picture =
        studio_image(render, job.cancel(), format_has_alpha(target.string()));
    job.progress(-1, "writing", target.filename().string());
    WriteOptions write = picture.write;
    write.bits = bits;
    OutputOptions output = policy;
    output.cancel = job.cancel();
    OutputFile file(target, output);
    write_image(file, picture.image, write);
    file.commit();
    job.add_file(target.filename().string());
  });
}

int submit_filter(JobQueue& jobs, const json& body, StudioContext& context) {
  const engine::Drawing drawing = drawing_from_json(body);
  std::optional<Ifs> colouring = colouring_for_drawing(body, drawing);  // the count checked
  const std::string movie = required_text(body, "movie");
  FilterArgs args;
  args.input = context.movie_path(movie).string();
  args.output = output_name(body, context, {".mp4", ".mkv", ".mov", ".avi", ".webm"}).string();
  args.quiet = true;
  args.fractal.engine.exact = bool_field(body, "exact", true);
  args.fractal.exact_given = body.contains("exact");  // refused for a flame (settings_of)
  args.fractal.exact_name = "exact";
  args.fractal.view = text_field(body, "view", "");
  args.fractal.engine.mix = number_field(body, "mix", 0, 0, 1);
  args.fractal.background = text_field(body, "background", "black");
  args.fractal.engine.drift_amount =
      number_field(body, "drift_amount", engine::kDefaultDriftAmount, 0, engine::kMaxDriftAmount);
  args.fractal.engine.drift_speed =
      number_field(body, "drift_speed", engine::kDefaultDriftSpeed, 0, engine::kMaxDriftSpeed);
  args.fractal.engine.sampling.seed =
      static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  args.animate = choice_field(body, "animate", "none", {"none", "drift"}) == "drift"
                     ? engine::Animate::drift
                     : engine::Animate::none;
  args.keyframe_interval =
      static_cast<int>(integer_field(body, "keyframe_interval", engine::kDefaultKeyframeInterval, 1,
                                     engine::kMaxKeyframeInterval));
  args.frames = text_field(body, "frames", "");
  args.size = text_field(body, "size", "");
  // `ifsfx filter`'s own checks, then the output policy, before the job is queued.
  check_filter_args(args);
  view_option(args.fractal.view, "view");  // the page's names in the messages
  engine::parse_background(args.fractal.background, "background");
  // The fractal as data: the editor's preset or flame and colouring IFS G (steal mode), fitted as
  // `--colouring` is, with the view and background parsed as the command parses them.
  const engine::FractalSettings fractal = args.fractal.settings_of(drawing, std::move(colouring));
  OutputOptions policy{.inputs = context.inputs()};
  policy.inputs.add(args.input);
  check_output(args.output, policy);
  const std::string name = fs::path(args.output).filename().string();
  JobSpec spec{.kind = "filter", .title = name, .writes = {args.output}, .reads = {args.input}};
  return jobs.submit(std::move(spec), [args, fractal, policy, name](JobContext& job) {
    job.progress(-1, "preparing", "the steal map");
    FilterRun run;
    run.stop = job.stop();
    run.inputs = policy.inputs;
    run.note = [&job](const std::string& line) { job.progress(-1, "preparing", line); };
    run.progress = [&job](const video::Progress& p) {
      job.progress(p.total > 0 ? static_cast<double>(p.done) / p.total : -1, "filtering",
                   p.total > 0 ? fmt::format("{}/{} frames, {:.1f} fps", p.done, p.total, p.fps())
                               : fmt::format("{} frames, {:.1f} fps", p.done, p.fps()));
    };
    const FilterOutcome out = filter_movie(args, fractal, run);
    if (out.result.interrupted) {
      // As `ifsfx filter` does: the frames done stay playable beside the output.
      if (!out.result.partial.empty()) job.add_file(out.result.partial.filename().string());
      throw Error(
          ErrorKind::interrupted,
          out.result.partial.empty()
              ? fmt::format("cancelled after {} frames; nothing written", out.result.frames_written)
              : fmt::format("cancelled: {} frames kept in {}", out.result.frames_written,
                            out.result.partial.filename().string()));
    }
    job.add_file(name);
  });
}

int submit_texture(JobQueue& jobs, const json& body, StudioContext& context) {
  if (!body.contains("superifs"))
    throw Error(ErrorKind::parse, "superifs: must be given (got nothing)");
  const SuperIfsPreset preset = superifs_from_json(body["superifs"]);
  const fs::path first = output_name(body, context, {".png", ".tif", ".tiff", ".exr", ".jpg"});
  TextureArgs args;
  args.output =
      (first.parent_path() / (first.stem().string() + "_%04d" + first.extension().string()))
          .string();
  args.size = text_field(body, "size", "512x512");
  args.count = static_cast<int>(integer_field(body, "V", 3, 1, 64));
  args.buffer = static_cast<int>(integer_field(body, "buffer", 1, 1, args.count));
  args.mode = parse_texture_mode(
      choice_field(body, "mode", "attractor", {"attractor", "tops", "steal", "measure"}), "mode");
  args.frames = static_cast<int>(integer_field(body, "frames", 1, 1, 1000));
  args.crossfade = static_cast<int>(integer_field(body, "crossfade", 1, 1, 100));
  args.steps = static_cast<int>(integer_field(body, "steps", 0, 0, 500));
  args.seed = static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  if (args.mode == TextureMode::steal)
    args.source = context.source_path(text_field(body, "source", "sample")).string();
  args.quiet = true;
  const cv::Size size = check_texture_args(args);
  if (size.width > 4096 || size.height > 4096)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("size: at most 4096x4096 in the studio (got {})", args.size));
  OutputOptions policy{.inputs = context.inputs()};
  policy.inputs.add(args.source);
  JobSpec spec{.kind = "texture"};
  for (int frame = 1; frame <= args.frames; ++frame) {
    const fs::path path = video::sequence_path(args.output, frame);
    check_output(path, policy);
    spec.writes.push_back(path.string());
  }
  spec.title = fmt::format("{} ({} frame{})", fs::path(spec.writes.front()).filename().string(),
                           args.frames, args.frames == 1 ? "" : "s");
  if (!args.source.empty()) spec.reads.push_back(args.source);
  return jobs.submit(std::move(spec), [preset, args, policy](JobContext& job) {
    job.progress(0, "burn-in", fmt::format("V = {}", args.count));
    TextureRun run;
    run.cancel = job.cancel();
    run.inputs = policy.inputs;
    run.progress = [&job](int done, int total) {
      job.progress(static_cast<double>(done) / total, "rendering",
                   fmt::format("{}/{} frames", done, total));
    };
    const TextureOutcome out = write_textures(preset, args, run);
    for (const auto& file : out.files) job.add_file(file.filename().string());
  });
}

}  // namespace

int submit_render_job(JobQueue& jobs, const json& body, StudioContext& context) {
  const std::string kind = choice_field(body, "kind", "", {"still", "filter", "texture"});
  if (kind == "still") return submit_still(jobs, body, context);
  if (kind == "filter") return submit_filter(jobs, body, context);
  return submit_texture(jobs, body, context);
}

}  // namespace ifsfx::app
