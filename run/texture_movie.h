// SPDX-License-Identifier: Apache-2.0
// `ifsfx texture --frames N -o loop.mp4` (.webm, .gif, animated .webp, any container FFmpeg
// writes): the frames of a texture sequence or loop into one movie, through the movie pipeline and
// writer of `ifsfx filter` (video/pipeline.h, video/file_sink.h) — the output policy, a playable
// OUTPUT-STEM.partial.EXT of the frames done after Ctrl-C, GIF and WebP looping for ever.
#pragma once

#include <functional>
#include <string>

#include <cstdint>

#include <opencv2/core.hpp>

#include "ifs/output_file.h"
#include "ifs/tiles.h"
#include "run/texture_options.h"
#include "superifs/texture.h"

namespace ifsfx::app {

// Whether -o names a movie: a container FFmpeg writes, not a numbered pattern. A single frame
// (no --loop) to .gif or .webp is a still image, as before movies were written.
bool writes_texture_movie(const TextureArgs& args);

// Checks a movie output before any work — its encoder, 8 bits, the output policy — and returns the
// frame size the encoder takes: even sides for 4:2:0 encoders (H.264, VP9), one pixel smaller
// than --size where a side is odd, said to `note` (one line, "note: ...").
cv::Size check_texture_movie(const TextureArgs& args, cv::Size size, const OutputOptions& output,
                             const std::function<void(const std::string&)>& note = {});

// Writes frames first..last of `textures` (crossfaded, or placed in the loop), each laid out as
// `layout` says (--seamless --tiles), into the movie and returns how many. A stop or an error keeps
// the frames done as OUTPUT-STEM.partial.EXT and throws (Error{interrupted} naming it after
// Ctrl-C).
std::int64_t write_texture_movie(const TextureArgs& args, TextureSequence& textures,
                                 const TileLayout& layout, const OutputOptions& output,
                                 std::int64_t first, std::int64_t last);

}  // namespace ifsfx::app
