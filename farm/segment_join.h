// SPDX-License-Identifier: Apache-2.0
// The join of a sharded filter run: the segments' video packets concatenated into one movie by
// stream copy (no re-encoding), with the input's audio copied as a single run copies it.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "ifs/output_file.h"

namespace ifsfx::farm {

struct JoinOptions {
  // Movie files made by `ifsfx filter --segment` (each on the source's clock, so that every
  // packet keeps its place in the whole), in order; they must share one encoding.
  std::vector<std::filesystem::path> segments;
  std::filesystem::path output;  // container by extension; written under the output policy
  // The input whose audio streams are copied, packet for packet, in sync with the video.
  std::optional<std::filesystem::path> audio_from;
  double audio_origin = 0;  // the time on audio_from's clock of the input's frame 0
  // The output policy (ifs/output_file.h): the inputs OUTPUT must not be (the segments are added
  // by the join), and the stop request, polled between packets.
  OutputOptions policy;
};

struct JoinResult {
  std::int64_t video_packets = 0;
  std::int64_t bytes = 0;  // size of the output
  double seconds = 0;      // duration of the video
};

// Concatenates the segments: the first frame of the first segment is output time 0, and the
// timestamps run on continuously across segments. Throws Error{not_found} for a missing segment,
// Error{unsupported} for segments whose encodings differ (a stream copy would be invalid),
// Error{invalid_argument} when OUTPUT is one of the inputs, Error{io} for a write failure and
// Error{interrupted} for a stop request; after any of them the temporary file is removed and an
// existing OUTPUT is left as it was (the segments stay: the join can run again).
JoinResult join_segments(const JoinOptions& options);

}  // namespace ifsfx::farm
