// SPDX-License-Identifier: Apache-2.0
#include "run/texture_run.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "run/arguments.h"
#include "run/seamless_options.h"
#include "run/texture_movie.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"

namespace ifsfx::app {
namespace {

// Where frame j goes: a numbered pattern (tex_%04d.png) numbers the frames from 1, also a single
// one; a movie (.mp4, .webm, .gif, .webp, ...) holds them all (run/texture_movie.h).
struct FrameFiles {
  std::string output;
  bool numbered = false, movie = false;
  int first = 0, last = 0;  // the frames this run writes, from 0

  std::filesystem::path path_of(int frame) const {
    return numbered ? video::sequence_path(output, frame + 1) : std::filesystem::path(output);
  }
};

FrameFiles frame_files(const TextureArgs& args) {
  video::check_output_name(args.output);
  FrameFiles files{.output = args.output,
                   .numbered = video::is_sequence_pattern(args.output),
                   .movie = writes_texture_movie(args),
                   .last = args.frames - 1};
  if (args.frames > 1 && !files.numbered && !files.movie)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("-o: --frames needs a numbered pattern like tex_%04d.png or a movie "
                            "(.mp4, .webm, .gif, .webp, ...) (got {})",
                            args.output));
  // A farm shard writes its own frames; each is a pure function of its index (map_at).
  if (!args.frame_range.empty()) {
    const video::FrameRange range = video::parse_frame_range(args.frame_range, "--frame-range");
    files.first = static_cast<int>(std::min<std::int64_t>(range.first, args.frames));
    if (range.last >= 0)
      files.last = static_cast<int>(std::min<std::int64_t>(range.last, files.last));
  }
  return files;
}

// The output policy: no frame replaces an input; every name is checked before the burn-in.
// Returns the size of the frames (a 4:2:0 movie encoder takes even sides: run/texture_movie.h).
cv::Size check_frame_files(const TextureArgs& args, const FrameFiles& files, cv::Size size,
                           OutputOptions& output, const TextureRun& run) {
  add_preset_input(output.inputs, args.preset);
  output.inputs.add(args.source);
  if (files.movie) return check_texture_movie(args, size, output, run.note);
  if (files.first <= files.last)
    check_writable_image(files.path_of(files.first), output, args.bits);
  for (int frame = files.first + 1; frame <= files.last; ++frame)
    check_output(files.path_of(frame), output);
  return size;
}

// The library's options of the arguments. --seamless: the buffers on the torus of the tile (the
// preset's [seamless] view, else its view, else the union attractor framed with no margin).
TextureOptions texture_options(const SuperIfsPreset& preset, const TextureArgs& args,
                               const CancelToken& cancel) {
  TextureOptions options{.sampling = {.seed = args.seed, .threads = args.threads, .cancel = cancel},
                         .count = args.count,
                         .steps = args.steps,
                         .buffer = args.buffer - 1,
                         .mode = args.mode};
  if (args.tiles.seamless) {
    options.sampling.seamless = true;
    options.sampling.margin = 0;
    if (preset.seamless) options.sampling.view = preset.seamless->view;
  }
  options.loop = args.loop > 0 ? steps_in_loop(args.loop, args.crossfade) : 0;
  if (!args.source.empty()) options.source = read_image(args.source).pixels;
  return options;
}

// The metadata of the frame that shows step `step` of the sequence: the superpreset, the
// settings and the command that makes it again.
WriteOptions frame_metadata(const SuperIfsPreset& preset, const std::string& name,
                            const TextureArgs& args, int step,
                            const std::vector<std::pair<std::string, std::string>>& seamless) {
  WriteOptions write;
  write.bits = args.bits;
  write.metadata = {
      {"ifsfx:superpreset", preset.text},
      {"ifsfx:superpreset_name", name},
      {"ifsfx:mode", to_string(args.mode)},
      {"ifsfx:V", std::to_string(args.count)},
      {"ifsfx:buffer", std::to_string(args.buffer)},
      {"ifsfx:seed", std::to_string(args.seed)},
      {"ifsfx:steps", std::to_string(step)},
      {"ImageDescription", fmt::format("ifsfx texture {} -V {} --mode {} --seed {} --steps {}",
                                       name, args.count, to_string(args.mode), args.seed, step)},
  };
  if (args.loop > 0) {  // the loop's burn-in is its own: --steps does not say which texture
    write.metadata.back().second =
        fmt::format("ifsfx texture {} -V {} --mode {} --seed {} --loop {} --crossfade {}", name,
                    args.count, to_string(args.mode), args.seed, args.loop, args.crossfade);
    write.metadata.emplace_back("ifsfx:loop", std::to_string(args.loop));
  }
  for (const auto& entry : seamless) write.metadata.push_back(entry);
  return write;
}

// Frame j shows step s = j / K of the sequence crossfaded towards step s + 1 by (j mod K) / K.
// The frames are written to temporary files and put in place together at the end: a run that
// fails or is stopped leaves every existing frame file as it was. Returns the files written.
std::vector<std::filesystem::path> write_frame_files(
    const SuperIfsPreset& preset, const std::string& name, const TextureArgs& args,
    const FrameFiles& files, TextureSequence& textures, const TileLayout& layout,
    const OutputOptions& output, const TextureRun& run) {
  // A loop of L frames shows ⌈L / K⌉ textures, each K frames or a little less (ifs/timeline.h).
  const auto position_of = [&](std::int64_t frame) {
    return args.loop > 0 ? position_in_loop(frame, args.crossfade, args.loop)
                         : position_of_frame(frame, args.crossfade);
  };
  std::vector<OutputFile> written;
  for (int frame = files.first; frame <= files.last; ++frame) {
    const StepPosition position = position_of(frame);
    OutputFile file(files.path_of(frame), output);
    const int step = textures.burn_in() + static_cast<int>(position.step);
    std::vector<std::pair<std::string, std::string>> seamless;
    if (args.tiles.seamless)
      seamless = seamless_metadata(textures.buffers().viewport().view, layout);
    write_image(file, laid_out(textures.frame_at(position), layout),
                frame_metadata(preset, name, args, step, seamless));
    written.push_back(std::move(file));
    if (run.progress) run.progress(frame - files.first + 1, files.last - files.first + 1);
  }
  commit_together(written);
  std::vector<std::filesystem::path> paths;
  for (const OutputFile& file : written) paths.push_back(file.target());
  return paths;
}

}  // namespace

TextureOutcome write_textures(const SuperIfsPreset& preset, const TextureArgs& args,
                              const TextureRun& run) {
  cv::Size size = check_texture_args(args);
  const FrameFiles files = frame_files(args);
  OutputOptions output{.inputs = run.inputs, .cancel = run.cancel};
  size = check_frame_files(args, files, size, output, run);
  // --seamless: laid out as --tiles and --tile-offset say.
  const TileLayout layout = tile_layout(args.tiles, preset.seamless, size);
  const TextureOptions options = texture_options(preset, args, output.cancel);

  const auto start = std::chrono::steady_clock::now();
  TextureSequence textures(preset.super, size, options);
  TextureOutcome out;
  out.name = preset.super.name.empty() ? args.preset : preset.super.name;
  out.burn_in = textures.burn_in();
  out.loop_closed = args.loop == 0 || textures.loop_closed();
  if (files.movie) {
    out.frames = static_cast<int>(
        write_texture_movie(args, textures, layout, output, files.first, files.last));
    out.files.emplace_back(args.output);
  } else {
    out.files = write_frame_files(preset, out.name, args, files, textures, layout, output, run);
    out.frames = static_cast<int>(out.files.size());
  }
  out.size = size;
  out.steps_done = textures.steps_done();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace ifsfx::app
