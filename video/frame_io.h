// SPDX-License-Identifier: Apache-2.0
// Frame sources and sinks: the small interfaces every video input (movie file, image sequence,
// V4L2 camera) and output (movie file, image sequence, window, V4L2 output device) sits behind.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::video {

// A time base or a frame rate as an exact fraction (1/15360, 30000/1001), as containers store it.
struct Rational {
  int num = 0;
  int den = 1;
  double value() const { return den == 0 ? 0.0 : static_cast<double>(num) / den; }
  bool positive() const { return num > 0 && den > 0; }
};

// A rate given in frames per second as an exact fraction: whole rates as N/1, NTSC-like ones
// (29.97, 59.94, 23.976) as N·1000/1001, others to the nearest 1/1000000. 0/1 for a rate that is
// not positive and finite.
Rational rate_from_fps(double fps);

// One decoded frame: 8-bit BGR (CV_8UC3), as OpenCV decodes.
//
// `index` counts the frames as the source delivers them (presentation order, from 0), whatever
// their timestamps: a variable-rate movie's frame 100 is its 101st picture, not the picture at
// 100 / fps seconds. Frame ranges (--frames) and animations (--animate keyframes) count in it.
// Time is `timestamp`, exact as `pts` × `time_base` where the source has a clock.
struct Frame {
  cv::Mat image;
  std::int64_t index = 0;  // position in the source, from 0
  double timestamp = 0;    // seconds since the start of the source (capture time for cameras)
  // The exact time on the source's own clock, for sources that have one (movie files, image
  // sequences): timestamp = pts × time_base, and the frame is shown for duration × time_base
  // seconds (0: not known). time_base 0/1 (cameras): timestamp is all there is.
  std::int64_t pts = 0;
  std::int64_t duration = 0;
  Rational time_base{0, 1};
};

// An image as a frame: 8-bit BGR (CV_8UC3), grey expanded, alpha dropped with the colour kept,
// 16-bit and float (0..1) scaled. Throws Error{unsupported} for 2 channels or more than 4.
cv::Mat to_bgr8(const cv::Mat& image);

// A sound track that goes with a source's frames: the file that holds it, and the time on that
// file's clock that Frame::timestamp 0 stands for.
struct AudioTrack {
  std::filesystem::path file;
  double origin = 0;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The next frame, or nothing at the end of the stream. Throws ifsfx::Error on a fault (a
  // corrupt file, a camera that vanished), naming the source.
  virtual std::optional<Frame> read() = 0;
  // Moves past the next frame without delivering it (a frame range that starts later): false at
  // the end of the stream. Sources override it to skip the work of making the image.
  virtual bool skip() { return read().has_value(); }
  // Moves a source that has not given a frame yet to frame `index` (counted as Frame::index
  // counts), so that the next read() gives exactly that frame: false when the source ends before
  // it. The default skips the frames before; a movie file seeks to the keyframe at or before the
  // frame's time and decodes forward from there (a shard of a long film starts at once).
  virtual bool seek(std::int64_t index) {
    for (std::int64_t i = 0; i < index; ++i)
      if (!skip()) return false;
    return true;
  }
  virtual cv::Size size() const = 0;
  virtual double fps() const = 0;  // frames per second; 0 when unknown
  // The nominal rate, exact: a movie file's own fraction, rate_from_fps(fps()) by default.
  virtual Rational frame_rate() const { return rate_from_fps(fps()); }
  // The clock of Frame::pts; 0/1 for a source without one (cameras: Frame::timestamp only).
  virtual Rational time_base() const { return {0, 1}; }
  virtual std::int64_t frame_count() const { return -1; }  // -1 when unknown (cameras)
  virtual std::string name() const = 0;                    // path or device, for messages
  // The files the frames are read from (a movie file, every file of an image sequence), which no
  // output may replace; none for a device.
  virtual std::vector<std::filesystem::path> files() const { return {}; }
  // The sound track to copy into a movie of these frames (a movie file's); none by default.
  virtual std::optional<AudioTrack> audio() const { return std::nullopt; }
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Throws ifsfx::Error on a fault (disk full, device gone), naming the sink.
  virtual void write(const Frame& frame) = 0;
  // Finalises the output after its last frame (trailer, rename into place). Idempotent.
  virtual void close() = 0;
  // Ends an output that did not complete (an error, a stop request) under the output policy
  // (ifs/output_file.h): a file it would have replaced keeps its contents; the frames written
  // are kept under a separate name where that is useful (a playable partial movie) and that name
  // is returned, else nothing is kept and the result is empty. Never throws. Sinks that write no
  // file (a window, a device) just close. The destructor of a sink that was neither closed nor
  // abandoned abandons it.
  virtual std::filesystem::path abandon() noexcept {
    try {
      close();
    } catch (...) {
    }
    return {};
  }
  virtual std::string name() const = 0;
};

}  // namespace ifsfx::video
