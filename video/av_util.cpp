#include "video/av_util.h"

#include <fmt/format.h>

namespace ifsfx::video::detail {

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
