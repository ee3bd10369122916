// SPDX-License-Identifier: Apache-2.0
// What the studio's job, video and superIFS handlers need of the studio (docs/studio.md): the
// folder, a private scratch folder for temporary files, the files no output may replace, and how
// the page's names of sources and movies become files.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
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

class StudioContext {
 public:
  StudioContext(std::filesystem::path folder, std::filesystem::path scratch,
                std::function<InputFiles()> inputs,
                std::function<std::filesystem::path(const std::string&)> source_path,
                std::function<std::filesystem::path(const std::string&)> movie_path)
      : folder_(std::move(folder)),
        scratch_(std::move(scratch)),
        inputs_(std::move(inputs)),
        source_path_(std::move(source_path)),
        movie_path_(std::move(movie_path)) {}

  // --folder, canonical: its files by folder_file(folder(), NAME, ...) (studio/folder.h).
  const std::filesystem::path& folder() const { return folder_; }
  // The files no output may replace: the presets the studio opened, --source.
  InputFiles inputs() const { return inputs_(); }
  // A steal source ("sample", "@source" or a file of the folder) as a readable file; throws
  // Error{invalid_argument} or Error{not_found} naming it.
  std::filesystem::path source_path(const std::string& name) const { return source_path_(name); }
  // A movie ("@source" or a file of the folder), likewise.
  std::filesystem::path movie_path(const std::string& name) const { return movie_path_(name); }
  // A fresh name in the scratch folder ending in `suffix`, for a file the caller creates and
  // removes (ScratchFile).
  std::filesystem::path scratch_name(const std::string& suffix) {
    return scratch_ / fmt::format("s{}{}", next_++, suffix);
  }

 private:
  std::filesystem::path folder_;
  std::filesystem::path scratch_;
  std::function<InputFiles()> inputs_;
  std::function<std::filesystem::path(const std::string&)> source_path_, movie_path_;
  std::atomic<long> next_{1};
};

}  // namespace ifsfx::app
