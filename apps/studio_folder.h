// SPDX-License-Identifier: Apache-2.0
// The one folder `ifsfx studio` reads and writes (--folder, docs/studio.md): files are named by
// plain names only, so that no request reaches a file elsewhere.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ifsfx::app {

class StudioFolder {
 public:
  // Throws Error{invalid_argument} when `folder` is not a folder.
  explicit StudioFolder(const std::filesystem::path& folder);

  const std::filesystem::path& root() const { return root_; }

  // The file `name` names in the folder: one path component of letters, digits and `_.+ -`, not
  // starting with a dot (no hidden file, no `..`). With `must_exist`, a regular file inside the
  // folder once links are followed (Error{not_found} when missing); without, the path to write.
  // Throws Error{invalid_argument} naming the rule otherwise.
  std::filesystem::path file(const std::string& name, bool must_exist) const;

  // Whether `name` passes file()'s rules for a name (without looking at the disk).
  static bool plain_name(const std::string& name);

  // The plain names of the folder's files that file(name, true) opens, whose extension (lower
  // case, with the dot) is one of `extensions`, sorted.
  std::vector<std::string> list(const std::vector<std::string>& extensions) const;

 private:
  std::filesystem::path root_;  // canonical
};

// The extension of `name`, lower case, with its dot: ".png".
std::string lower_extension(const std::filesystem::path& name);

}  // namespace ifsfx::app
