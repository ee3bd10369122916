// SPDX-License-Identifier: Apache-2.0
#include "run/texture_movie.h"

#include "run/movie_size.h"

#include <string>

#include <fmt/format.h>

#include "ifs/error.h"
#include "run/seamless_options.h"
#include "video/file_sink.h"
#include "video/file_source.h"
#include "video/image_sequence.h"
#include "video/pipeline.h"
#include "video/texture_frames.h"

namespace ifsfx::app {

bool writes_texture_movie(const TextureArgs& args) {
  if (video::is_sequence_pattern(args.output) || !video::is_movie_name(args.output)) return false;
  const std::string ext = std::filesystem::path(args.output).extension().string();
  const bool also_an_image = ext == ".gif" || ext == ".GIF" || ext == ".webp" || ext == ".WEBP";
  return !(also_an_image && args.frames == 1 && args.loop == 0);
}

cv::Size check_texture_movie(const TextureArgs& args, cv::Size size, const OutputOptions& output,
                             const std::function<void(const std::string&)>& note) {
  video::silence_libav_log();  // errors come as one line each, the encoders' chatter not at all
  if (args.bits != 8)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--bits: a movie has 8 bits per channel (got {} for {})", args.bits,
                            args.output));
  check_output(args.output, output);
  return encodable_movie_size(args.output, args.codec, size, note);
}

std::int64_t write_texture_movie(const TextureArgs& args, TextureSequence& textures,
                                 const TileLayout& layout, const OutputOptions& output,
                                 std::int64_t first, std::int64_t last) {
  const video::Rational rate = video::rate_from_fps(args.fps);
  video::TextureFrames source(textures, {.frames = args.frames,
                                         .crossfade = args.crossfade,
                                         .loop = args.loop,
                                         .rate = rate,
                                         .name = args.preset});
  video::FileSinkOptions o;
  o.codec = args.codec;
  o.size = {source.size().width * layout.tiles.width, source.size().height * layout.tiles.height};
  o.frame_rate = rate;
  o.time_base = source.time_base();
  o.threads = args.threads;
  o.output = output;
  video::FileSink movie(args.output, o);
  video::PipelineOptions pipeline;
  pipeline.range = {first, last};
  pipeline.stop = output.cancel.flag();
  const video::PipelineResult result = video::run_pipeline(
      source, movie, [&](const video::Frame& frame) { return laid_out(frame.image, layout); },
      pipeline);
  if (result.interrupted)
    throw Error(
        ErrorKind::interrupted,
        result.partial.empty()
            ? fmt::format("interrupted after {} frames; nothing written ({} left as it was)",
                          result.frames_written, args.output)
            : fmt::format("interrupted: {} frames kept in {} ({} left as it was)",
                          result.frames_written, result.partial.string(), args.output));
  return result.frames_written;
}

}  // namespace ifsfx::app
