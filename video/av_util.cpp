// SPDX-License-Identifier: Apache-2.0
#include "video/av_util.h"

#include <algorithm>

#include <fmt/format.h>

#include "ifs/parallel.h"

namespace ifsfx::video::detail {

int codec_threads(int requested) {
  constexpr int kMaxCodecThreads = 16;  // libavcodec's own cap for an automatic count
  if (requested == 0) return 0;
  return std::min(resolve_threads(requested), kMaxCodecThreads);
}

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

int check_av(int code, ErrorKind kind, const std::string& what, const std::string& rule) {
  if (code < 0) throw Error(kind, fmt::format("{}: {} ({})", what, rule, av_message(code)));
  return code;
}

}  // namespace ifsfx::video::detail
