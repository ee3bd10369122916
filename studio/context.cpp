// SPDX-License-Identifier: Apache-2.0
#include "studio/context.h"

#include "ifs/error.h"

namespace ifsfx::app {

namespace fs = std::filesystem;

StudioContext::StudioContext(fs::path folder, fs::path web, fs::path scratch, fs::path source)
    : folder_(std::move(folder)),
      web_(std::move(web)),
      scratch_(std::move(scratch)),
      source_(std::move(source)),
      source_is_movie_(!source_.empty() && is_movie_name(source_)) {
  if (!source_.empty()) inputs_.add(source_);
}

InputFiles StudioContext::inputs() const {
  std::lock_guard lock(mutex_);
  return inputs_;
}

void StudioContext::add_input(const fs::path& path) {
  std::lock_guard lock(mutex_);
  inputs_.add(path);
}

fs::path StudioContext::source_path(const std::string& name) const {
  if (name == "sample") return web_ / "sample.png";
  if (name == kSourceName && has_source_image()) return source_;
  if (!is_image_name(name))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("source: an image of --folder (got '{}')", name));
  return folder_file(folder_, name, true);
}

fs::path StudioContext::movie_path(const std::string& name) const {
  if (name == kSourceName && has_source_movie()) return source_;
  const fs::path path = folder_file(folder_, name, true);
  if (!is_movie_name(path))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("movie: a movie file ({}) of --folder (got '{}')",
                            ".mp4, .mkv, .mov, .avi, .webm, ...", name));
  return path;
}

}  // namespace ifsfx::app
