// SPDX-License-Identifier: Apache-2.0
#include "apps/studio_folder.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::app {

namespace fs = std::filesystem;

StudioFolder::StudioFolder(const fs::path& folder) {
  std::error_code ec;
  root_ = fs::canonical(folder, ec);
  if (ec || !fs::is_directory(root_))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--folder {}: must be a folder", folder.string()));
}

bool StudioFolder::plain_name(const std::string& name) {
  if (name.empty() || name.size() > 255 || name.find("..") != std::string::npos) return false;
  const auto allowed = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '+' ||
           c == ' ' || c == '-';
  };
  const bool first = std::isalnum(static_cast<unsigned char>(name[0])) || name[0] == '_';
  return first && std::all_of(name.begin(), name.end(), allowed);
}

fs::path StudioFolder::file(const std::string& name, bool must_exist) const {
  if (!plain_name(name))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a plain name in --folder (got '{}')", name));
  const fs::path path = root_ / name;
  if (!must_exist) return path;
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  if (ec || !fs::is_regular_file(real))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file in --folder", name));
  if (real.parent_path() != root_)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: leads out of --folder (got {})", name, real.string()));
  return real;
}

std::vector<std::string> StudioFolder::list(const std::vector<std::string>& extensions) const {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(root_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!plain_name(name)) continue;
    const std::string ext = lower_extension(name);
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) continue;
    // Only what file() would open: no link that leads out of the folder.
    const fs::path real = fs::canonical(entry.path(), ec);
    if (!ec && real.parent_path() == root_ && fs::is_regular_file(real, ec)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string lower_extension(const fs::path& name) {
  std::string ext = name.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace ifsfx::app
