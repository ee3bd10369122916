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

TextureOutcome write_textures(const SuperIfsPreset& preset, const TextureArgs& args,
                              const TextureRun& run) {
  cv::Size size = check_texture_args(args);
  // A numbered pattern (tex_%04d.png) numbers the frames from 1, also a single one; a movie
  // (.mp4, .webm, .gif, .webp, ...) holds them all (run/texture_movie.h).
  video::check_output_name(args.output);
  const bool numbered = video::is_sequence_pattern(args.output);
  const bool movie = writes_texture_movie(args);
  if (args.frames > 1 && !numbered && !movie)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("-o: --frames needs a numbered pattern like tex_%04d.png or a movie "
                            "(.mp4, .webm, .gif, .webp, ...) (got {})",
                            args.output));
  // A loop of L frames shows ⌈L / K⌉ textures, each K frames or a little less (ifs/timeline.h).
  const auto position_of = [&](std::int64_t frame) {
    return args.loop > 0 ? position_in_loop(frame, args.crossfade, args.loop)
                         : position_of_frame(frame, args.crossfade);
  };
  const auto path_of = [&](int frame) -> std::filesystem::path {
    return numbered ? video::sequence_path(args.output, frame + 1)
                    : std::filesystem::path(args.output);
  };
  // A farm shard writes its own frames; each is a pure function of its index (map_at).
  int first = 0, last = args.frames - 1;
  if (!args.frame_range.empty()) {
    const video::FrameRange range = video::parse_frame_range(args.frame_range, "--frame-range");
    first = static_cast<int>(std::min<std::int64_t>(range.first, args.frames));
    if (range.last >= 0) last = static_cast<int>(std::min<std::int64_t>(range.last, last));
  }
  // The output policy: no frame replaces an input; every name is checked before the burn-in.
  OutputOptions output{.inputs = run.inputs, .cancel = run.cancel};
  add_preset_input(output.inputs, args.preset);
  output.inputs.add(args.source);
  if (movie) {
    size = check_texture_movie(args, size, output);
  } else {
    if (first <= last) check_writable_image(path_of(first), output, args.bits);
    for (int frame = first + 1; frame <= last; ++frame) check_output(path_of(frame), output);
  }
  // --seamless: the buffers on the torus of the tile (the preset's [seamless] view, else its view,
  // else the union attractor framed with no margin), laid out as --tiles and --tile-offset say.
  const TileLayout layout = tile_layout(args.tiles, preset.seamless, size);

  TextureOptions options{
      .sampling = {.seed = args.seed, .threads = args.threads, .cancel = output.cancel},
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

  const auto start = std::chrono::steady_clock::now();
  TextureSequence textures(preset.super, size, options);
  const std::string name = preset.super.name.empty() ? args.preset : preset.super.name;
  const auto metadata = [&](int step) {
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
    if (args.tiles.seamless)
      for (auto& entry : seamless_metadata(textures.buffers().viewport().view, layout))
        write.metadata.push_back(entry);
    return write;
  };

  // Frame j shows step s = j / K of the sequence crossfaded towards step s + 1 by (j mod K) / K.
  // The frames are written to temporary files and put in place together at the end: a run that
  // fails or is stopped leaves every existing frame file as it was.
  TextureOutcome out;
  out.name = name;
  out.burn_in = textures.burn_in();
  out.loop_closed = args.loop == 0 || textures.loop_closed();
  if (movie) {
    out.frames = static_cast<int>(write_texture_movie(args, textures, layout, output, first, last));
    out.files.emplace_back(args.output);
  }
  std::vector<OutputFile> written;
  for (int frame = first; frame <= last && !movie; ++frame) {
    const StepPosition position = position_of(frame);
    OutputFile file(path_of(frame), output);
    write_image(file, laid_out(textures.frame_at(position), layout),
                metadata(textures.burn_in() + static_cast<int>(position.step)));
    written.push_back(std::move(file));
    if (run.progress) run.progress(frame - first + 1, last - first + 1);
  }
  commit_together(written);
  out.size = size;
  out.steps_done = textures.steps_done();
  if (!movie) out.frames = static_cast<int>(written.size());
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const OutputFile& file : written) out.files.push_back(file.target());
  return out;
}

}  // namespace ifsfx::app
