// SPDX-License-Identifier: Apache-2.0
// Internal to the file sink: copies the audio streams of an input movie, packet for packet and
// unchanged, into the output being muxed, in step with the video so that the muxer can interleave
// them. Stream copy keeps the audio bit-exact and costs nothing; done with FFmpeg's libraries in
// the same muxer as the video (no second pass, no subprocess), so that a file closed early (Ctrl-C,
// a truncated input, a --frames range) carries exactly the audio of the frames it holds.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "video/av_util.h"

namespace ifsfx::video::detail {

class AudioCopy {
 public:
  // Opens `input` and adds to `output` one stream per audio stream of the input. Throws
  // Error{unsupported} when the output's container cannot hold one of them (e.g. PCM in .mp4),
  // before any frame is written. An input without audio adds nothing.
  AudioCopy(const std::filesystem::path& input, AVFormatContext* output,
            const std::string& output_name);
  ~AudioCopy();
  AudioCopy(const AudioCopy&) = delete;
  AudioCopy& operator=(const AudioCopy&) = delete;

  bool empty() const { return map_.empty(); }

  // Output time 0 is input time `origin` (seconds on the input's clock); set before copy_until.
  void set_origin(double origin) { origin_ = origin; }

  // Writes (interleaved) every audio packet that starts before output time `until` and has not
  // been written yet; packets that end before time 0 are dropped.
  void copy_until(double until);

 private:
  std::filesystem::path path_;
  AVFormatContext* output_;
  std::string output_name_;  // the final path, for messages
  std::unique_ptr<AVFormatContext, InputContextDeleter> input_;
  std::unique_ptr<AVPacket, PacketDeleter> packet_{av_packet_alloc()};
  std::vector<int> map_;  // input stream index → output stream index, -1 for streams not copied
  double origin_ = 0;
  bool pending_ = false;  // packet_ holds a packet read ahead, not yet due
  bool exhausted_ = false;
};

}  // namespace ifsfx::video::detail
