// SPDX-License-Identifier: Apache-2.0
// Numbered still images as a frame source and sink: "frame_%04d.png" and the like, read and
// written through OpenImageIO (ifs/image_io.h), so any format it handles can hold the frames.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ifs/output_file.h"
#include "video/frame_io.h"

namespace ifsfx::video {

// Whether `path` is a sequence pattern: it holds one printf number, %d or %0Nd.
bool is_sequence_pattern(const std::string& path);

// The file name of frame `index` of `pattern`. Throws Error{parse} unless the pattern holds
// exactly one %d or %0Nd (N ≤ 9) and no other '%'.
std::filesystem::path sequence_path(const std::string& pattern, std::int64_t index);

// Throws Error{parse} "WHAT: ..." for an output name with a '%' that is not one %d or %0Nd (N ≤ 9):
// such a name ("%5d", "%d%d", "%99999999999d") is neither a file name nor a pattern ifsfx writes.
void check_output_name(const std::string& name, const std::string& what = "-o");

struct ImageSequenceOptions {
  double fps = 25;  // the sequence's frame rate (images carry none)
  // A number missing between the first and the last file (frame_0001, frame_0002, frame_0004)
  // is an error unless this is set; then the sequence goes on with the next file, and the frame
  // before the gap is held for the missing time (Frame::duration).
  bool skip_gaps = false;
};

// Reads frames from the first number of 0..4 that exists (as ffmpeg does) to the highest number
// in the folder. File N is shown at (N − first) / fps seconds (Frame::pts = N − first on a clock
// of 1/fps); Frame::index counts the files read. Images are converted to 8-bit BGR (grey
// expanded, alpha dropped with the colour kept, 16-bit and float scaled).
// Throws Error{not_found} when no frame of the pattern exists, or naming the first missing file
// when the numbers have a gap (unless options.skip_gaps); Error{unsupported} for frames of
// differing sizes.
//   ImageSequenceSource in("shots/frame_%04d.png", {.fps = 24});
class ImageSequenceSource final : public FrameSource {
 public:
  explicit ImageSequenceSource(const std::string& pattern,
                               const ImageSequenceOptions& options = {});
  std::optional<Frame> read() override;
  bool skip() override;  // the image is not read
  cv::Size size() const override { return size_; }
  double fps() const override { return fps_; }
  Rational frame_rate() const override { return rate_; }
  Rational time_base() const override { return {rate_.den, rate_.num}; }
  std::int64_t frame_count() const override { return static_cast<std::int64_t>(numbers_.size()); }
  std::string name() const override { return pattern_; }
  // The files of the sequence, in order (they are the command's inputs).
  std::vector<std::filesystem::path> files() const override;

 private:
  std::string pattern_;
  double fps_;
  Rational rate_;
  std::vector<std::int64_t> numbers_;  // the files' numbers, ascending
  std::size_t next_ = 0;               // files read (or skipped) so far
  cv::Size size_;
};

struct ImageSequenceSinkOptions {
  std::int64_t first = 0;  // the number of the first frame written
  // Frames the caller expects to write (-1: unknown): their names are checked against the
  // inputs at construction, before any work.
  std::int64_t expected = -1;
  OutputOptions output;  // the output policy: the inputs no frame may replace
};

// Writes frame k (in order of writing) to sequence_path(pattern, first + k) under the output
// policy (ifs/output_file.h): each frame is encoded into a temporary file at once, and close()
// renames them all into place, so a run that fails or is stopped (abandon()) leaves every
// existing frame file of the pattern as it was and keeps nothing. Throws at construction, before
// any work, when the first file could not be written or a frame file would replace an input.
class ImageSequenceSink final : public FrameSink {
 public:
  explicit ImageSequenceSink(const std::string& pattern,
                             const ImageSequenceSinkOptions& options = {});
  void write(const Frame& frame) override;
  void close() override;
  std::filesystem::path abandon() noexcept override;
  std::string name() const override { return pattern_; }

 private:
  std::string pattern_;
  ImageSequenceSinkOptions options_;
  std::vector<OutputFile> staged_;  // written, not yet in place
};

}  // namespace ifsfx::video
