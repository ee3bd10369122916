// SPDX-License-Identifier: Apache-2.0
#include "run/movie_size.h"

#include <fmt/format.h>

#include "video/file_sink.h"

namespace ifsfx::app {

cv::Size encodable_movie_size(const std::string& output, const std::string& codec, cv::Size size,
                              const std::function<void(const std::string&)>& note) {
  const cv::Size fit = video::encodable_size(output, codec, size);
  if (fit != size && note)
    note(fmt::format(
        "note: {}: writing {}x{}, not {}x{}: {} codes colour at half resolution and needs even "
        "sides",
        output, fit.width, fit.height, size.width, size.height,
        video::resolve_encoder(output, codec)));
  return fit;
}

}  // namespace ifsfx::app
