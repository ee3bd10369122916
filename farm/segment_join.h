// The join of a sharded filter run: the segments' video packets concatenated into one movie by
// stream copy (no re-encoding), with the input's audio copied as a single run copies it.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

namespace ifsfx::farm {

struct JoinOptions {
  // Movie files made by `ifsfx filter --segment` (each on the source's clock, so that every
  // packet keeps its place in the whole), in order; they must share one encoding.
  std::vector<std::filesystem::path> segments;
  std::filesystem::path output;  // container by extension; written as OUTPUT.part, then renamed
  // The input whose audio streams are copied, packet for packet, in sync with the video.
  std::optional<std::filesystem::path> audio_from;
  double audio_origin = 0;  // the time on audio_from's clock of the input's frame 0
};

struct JoinResult {
  std::int64_t video_packets = 0;
  std::int64_t bytes = 0;  // size of the output
  double seconds = 0;      // duration of the video
};

// Concatenates the segments: the first frame of the first segment is output time 0, and the
// timestamps run on continuously across segments. Throws Error{not_found} for a missing segment,
// Error{unsupported} for segments whose encodings differ (a stream copy would be invalid),
// Error{io} for a write failure (the partial file is removed; OUTPUT is never touched).
JoinResult join_segments(const JoinOptions& options);

}  // namespace ifsfx::farm
