// SPDX-License-Identifier: Apache-2.0
// What the studio's handlers need of the studio (docs/studio.md): the folder, a private scratch
// folder for temporary files, the files no output may replace, and how the page's names of
// sources and movies become files.
#pragma once

#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "ifs/output_file.h"
#include "studio/folder.h"

namespace ifsfx::app {

// A file of the scratch folder, removed when the guard goes.
class ScratchFile {
 public:
  explicit ScratchFile(std::filesystem::path path) : path_(std::move(path)) {}
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// What the studio's handlers share of the studio: the folder, the page's files, a private scratch
// folder for temporary files, --source, the files no output may replace, and how the page's names
// of sources and movies become files. Safe to use from any request or job thread.
class StudioContext {
 public:
  // The name of --source in the page.
  static constexpr const char* kSourceName = "@source";

  // `folder` and `source` (or empty) canonical; `web` holds sample.png; `scratch` is private.
  StudioContext(std::filesystem::path folder, std::filesystem::path web,
                std::filesystem::path scratch, std::filesystem::path source);

  // --folder, canonical: its files by folder_file(folder(), NAME, ...) (studio/folder.h).
  const std::filesystem::path& folder() const { return folder_; }
  // The page's files (studio/web).
  const std::filesystem::path& web() const { return web_; }
  // The scratch folder, and a fresh name in it ending in `suffix`, for a file the caller
  // creates and removes (ScratchFile).
  const std::filesystem::path& scratch() const { return scratch_; }
  std::filesystem::path scratch_name(const std::string& suffix) {
    return scratch_ / fmt::format("s{}{}", next_++, suffix);
  }

  // --source (canonical), or empty; whether it is a movie (else an image).
  const std::filesystem::path& source() const { return source_; }
  bool source_is_movie() const { return source_is_movie_; }
  bool has_source_image() const { return !source_.empty() && !source_is_movie_; }
  bool has_source_movie() const { return !source_.empty() && source_is_movie_; }

  // The files no output may replace: the presets the studio opened, --source.
  InputFiles inputs() const;
  void add_input(const std::filesystem::path& path);

  // A steal source ("sample", "@source" or an image of the folder) as a readable file; throws
  // Error{invalid_argument} or Error{not_found} naming it.
  std::filesystem::path source_path(const std::string& name) const;
  // A movie ("@source" or a movie of the folder), likewise.
  std::filesystem::path movie_path(const std::string& name) const;

 private:
  std::filesystem::path folder_, web_, scratch_, source_;
  bool source_is_movie_ = false;
  mutable std::mutex mutex_;  // guards inputs_
  InputFiles inputs_;
  std::atomic<long> next_{1};
};

}  // namespace ifsfx::app
