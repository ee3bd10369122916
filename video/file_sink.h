// SPDX-License-Identifier: Apache-2.0
// A movie file as a frame sink, encoded and muxed with FFmpeg's libraries, under the output policy
// (ifs/output_file.h): the movie is written to a fresh temporary file beside the target and
// renamed over it by close(), so an unfinished movie never takes the output's name. A run that
// ends early (Ctrl-C, a damaged input) calls abandon(): an existing target is left as it was, and
// the frames written become a complete, playable movie of their own, OUTPUT-STEM.partial.EXT.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "ifs/output_file.h"
#include "video/file_source.h"
#include "video/frame_io.h"

namespace ifsfx::video {

// How output frames are placed in time (`ifsfx filter --fps-mode`).
enum class FrameTiming {
  automatic,  // keep, where the container stores each frame's time; constant where it cannot (AVI)
  keep,       // every frame at its own timestamp: a variable-rate input stays variable-rate
  constant,   // frame_rate exactly, by timestamp: each output slot n shows the last frame whose
              // time rounds to slot n or before — frames repeated over gaps, and of several
              // frames within one slot only the last kept (ffmpeg -fps_mode cfr)
};

struct FileSinkOptions {
  // Encoder name as ffmpeg knows it ("libx264", "h264", "mpeg4", "ffv1", "mjpeg", ...); empty =
  // the container's default, as ffmpeg chooses it: .mp4/.mkv → H.264 (libx264), .avi → MPEG-4
  // part 2. Encoder settings are ffmpeg's defaults (libx264: preset medium, CRF 23), except
  // MPEG-4 part 2, encoded at constant quality q 3 instead of ffmpeg's 200 kb/s.
  std::string codec;
  // Frame size; every frame written must have it. Sides must suit the encoder's pixel format
  // (even for 4:2:0 H.264): encodable_size() gives the nearest that does.
  cv::Size size;
  Rational frame_rate{25, 1};  // the nominal rate, and the rate of a constant-rate output
  // The clock of the frames' exact times (Frame::pts; FileSource::time_base()): kept timestamps
  // are written on it. 0/1 (cameras): Frame::timestamp, on the grid of frame_rate.
  Rational time_base{0, 1};
  FrameTiming timing = FrameTiming::automatic;
  int threads = 0;  // encoder threads; 0 = all cores
  // Copy the audio streams of this file unchanged into the output, in sync with the frames.
  std::optional<std::filesystem::path> audio_from;
  // The time on audio_from's clock that Frame::timestamp 0 stands for (FileSource::start_time).
  double audio_origin = 0;
  // Output time 0 is the source's time 0 (Frame::pts 0), not the first frame written: a segment
  // of a sharded run (`ifsfx farm`) keeps its place in the whole movie, for a stream-copy join.
  bool source_clock = false;
  // The output policy: the inputs the movie must not replace (ifs/output_file.h).
  OutputOptions output;
};

// Opens the output, checks everything that can be checked before work starts, and writes the
// header. Throws Error{unsupported} for an unknown container extension, an unknown codec, a codec
// the container cannot carry, Error{invalid_argument} for an output that is one of the inputs,
// and Error{io} for an output that cannot be written (folder missing, no permission) — all
// before any frame is encoded.
//   FileSink out("out.mp4", {.size = in.size(), .frame_rate = in.frame_rate()});
//   out.write(frame); ...; out.close();
class FileSink final : public FrameSink {
 public:
  FileSink(const std::filesystem::path& path, const FileSinkOptions& options);
  ~FileSink() override;
  FileSink(const FileSink&) = delete;
  FileSink& operator=(const FileSink&) = delete;

  // Times are relative to the first frame written, which is output time 0. FrameTiming::keep
  // stamps each frame with its own time (exact on options.time_base; moved one tick on where two
  // would collide) and duration, so a variable-rate source keeps its timing and its sync with the
  // audio. FrameTiming::constant holds one frame back until the next one says how many slots it
  // covers.
  void write(const Frame& frame) override;
  // Flushes the encoder, writes the audio up to the end of the last frame, the trailer, and
  // renames the file into place. Without any frame written, removes the temporary file and throws
  // Error{io}: an empty movie is not a playable file.
  void close() override;
  // Finishes the frames written as a playable movie STEM.partial.EXT beside the target (never
  // replacing a file) and returns its name; the target is not touched. With no frame written, or
  // when the movie cannot be finished, removes the temporary file and returns an empty path.
  std::filesystem::path abandon() noexcept override;
  std::string name() const override;

  std::int64_t frames_written() const;   // frames encoded so far (repeats included)
  std::int64_t frames_repeated() const;  // constant timing: extra copies written over gaps
  std::int64_t frames_dropped() const;   // constant timing: frames that fell in a full slot
  FrameTiming timing() const;            // keep or constant, as resolved for this file
  std::string codec_name() const;        // the encoder in use, e.g. "libx264"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Whether `path` names a movie container FileSink writes (.mp4, .mkv, .webm, .mov, .avi, .gif,
// .webp, ...): FFmpeg knows its extension as a container of video that is not a still image
// format. Never throws.
bool is_movie_name(const std::filesystem::path& path) noexcept;

// The encoder `codec` names (or the default of the container `path` names), checked as close() of
// a FileSink would check it; for --help and for errors before work. Throws as FileSink does.
std::string resolve_encoder(const std::filesystem::path& path, const std::string& codec);

// The frame size nearest `size` that the encoder takes in the pixel format a FileSink picks:
// each side rounded down to a multiple of its chroma block (2 for 4:2:0, e.g. H.264 in yuv420p),
// and never below one block. `size` itself when it already fits.
//   const cv::Size out = encodable_size("out.mp4", "", {641, 481});  // 640x480
cv::Size encodable_size(const std::filesystem::path& path, const std::string& codec, cv::Size size);

// What FrameTiming::automatic means for `path` and `codec`: constant for containers that store no
// per-frame times (AVI counts frames) and encoders bound to a list of rates (MPEG-1/2), keep
// otherwise. Throws Error{unsupported} when `requested` is keep and the file cannot keep times.
FrameTiming resolve_timing(const std::filesystem::path& path, const std::string& codec,
                           FrameTiming requested);

}  // namespace ifsfx::video
