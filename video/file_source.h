// A movie file as a frame source: any container and codec FFmpeg's libraries read (the backend of
// OpenCV's videoio), decoded to 8-bit BGR frames in presentation order.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "video/frame_io.h"

namespace ifsfx::video {

// A frame rate as an exact fraction (30000/1001 for NTSC), as containers store it.
struct Rational {
  int num = 0;
  int den = 1;
  double value() const { return den == 0 ? 0.0 : static_cast<double>(num) / den; }
};

struct FileSourceOptions {
  int threads = 0;  // decoder threads; 0 = all cores
};

// Opens `path` and its first video stream. Throws Error{not_found} for a missing file,
// Error{unsupported} for a file FFmpeg cannot read or one without a video stream.
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
  cv::Size size() const override;
  double fps() const override;
  // The container's frame count (or duration × rate); -1 when it says neither.
  std::int64_t frame_count() const override;
  std::string name() const override;

  Rational frame_rate() const;  // exact average frame rate; 25/1 when the file gives none
  bool has_audio() const;       // whether the file carries at least one audio stream
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
