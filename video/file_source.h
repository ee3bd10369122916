// SPDX-License-Identifier: Apache-2.0
// A movie file as a frame source: any container and codec FFmpeg's libraries read (the backend of
// OpenCV's videoio), decoded to 8-bit BGR frames in presentation order.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "video/frame_io.h"
#include "video/orientation.h"

namespace ifsfx::video {

struct FileSourceOptions {
  int threads = 0;  // decoder threads; 0 = all cores
};

// Opens `path` and its first video stream. Throws Error{not_found} for a missing file,
// Error{unsupported} for a file FFmpeg cannot read or one without a video stream.
//
// Frames carry their exact timestamps (Frame::pts on the stream's clock, time_base()), so a
// variable-rate movie keeps its timing. A file whose display matrix (or `rotate` tag) turns the
// picture gives its frames turned upright: a phone's portrait clip comes out portrait.
//
// A corrupt or truncated file is read as far as it decodes; then read() throws Error{io} saying
// how many frames were decoded of how many the container announced, so that a caller writing
// the frames has kept everything that could be decoded.
//   FileSource in("clip.mp4");
//   while (auto frame = in.read()) use(frame->image);
class FileSource final : public FrameSource {
 public:
  explicit FileSource(const std::filesystem::path& path, const FileSourceOptions& options = {});
  ~FileSource() override;
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  std::optional<Frame> read() override;
  bool skip() override;  // decodes (the next frames depend on it) but does not convert
  // Exact seeking by timestamp, for constant and variable rates: the presentation times of the
  // packets up to frame `index` are read (demuxing only, no decoding) to find that frame's time;
  // then the file seeks to the keyframe at or before it and decodes forward, dropping the frames
  // before. The frames given equal those of a sequential decode. A source that has already given
  // frames, or a stream without packet times, skips instead.
  bool seek(std::int64_t index) override;
  // The exact number of frames, counted by demuxing every video packet (no decoding; fast, but it
  // reads the whole file), on a source that has not given a frame yet; it stays at the start.
  std::int64_t count_frames();
  cv::Size size() const override;
  double fps() const override;
  // The container's frame count (or duration × rate); -1 when it says neither.
  std::int64_t frame_count() const override;
  std::string name() const override;
  std::vector<std::filesystem::path> files() const override { return {path()}; }
  // The file's own sound track, from start_time(), when it has one.
  std::optional<AudioTrack> audio() const override;

  // The nominal frame rate as ffmpeg guesses it (av_guess_frame_rate: the stream's base rate, so
  // a clip with dropped frames keeps its 30/1, not its average); 25/1 when the file gives none.
  // A variable-rate movie's frames come at their own times (Frame::pts), not on this grid.
  Rational frame_rate() const override;
  Rational time_base() const override;  // the clock of Frame::pts: the video stream's time base
  // How the file says its pictures are to be shown (display matrix or `rotate` tag). Frames come
  // turned upright already, and size() is the upright size.
  const Orientation& orientation() const;
  bool has_audio() const;  // whether the file carries at least one audio stream
  // Where Frame::timestamp 0 lies on the file's own clock, in seconds (for audio sync). Known
  // once the first frame has been read; the stream's start time before that.
  double start_time() const;
  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// libav writes its own diagnostics to stderr unless told otherwise; the command line calls this
// once (a process-wide libav setting, so it is the app's to make, not the library's).
void silence_libav_log();

}  // namespace ifsfx::video
