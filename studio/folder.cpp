// SPDX-License-Identifier: Apache-2.0
#include "studio/folder.h"

#include <algorithm>
#include <cctype>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "flame/flame_file.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "studio/render.h"

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::size_t kMaxListed = 1000;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return lower(s).ends_with(suffix);
}

// The plain names of the regular files of `folder` (links to files included), sorted.
std::vector<std::string> plain_files(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || !entry.is_regular_file(ec)) continue;
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

json summary_row(const std::string& file, const PresetSummary& s) {
  return {{"file", file},
          {"name", s.name},
          {"maps", s.maps},
          {"contraction", s.contraction},
          {"description", s.description},
          {"problem", s.problem}};
}

// ASCII letters, digits, `_ . + -` and spaces, starting with a letter, a digit or `_`, without
// `..`.
bool plain_name(const std::string& name) {
  const auto word = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  };
  if (name.empty() || name.size() > 200 || !word(name[0]) || name.find("..") != std::string::npos)
    return false;
  return std::all_of(name.begin(), name.end(), [&](char c) {
    return word(c) || c == '.' || c == '+' || c == ' ' || c == '-';
  });
}

bool flame_name(std::string_view name) {
  return ends_with(name, ".flame") || ends_with(name, ".flam3");
}

// The selector that picks flame `e` of its file: its name when no other flame of the file has
// it (read_flame picks the first of a name), else its index.
std::string flame_selector(const std::vector<flame::FlameEntry>& all, const flame::FlameEntry& e) {
  const auto named = std::count_if(all.begin(), all.end(),
                                   [&](const flame::FlameEntry& f) { return f.name == e.name; });
  return !e.name.empty() && named == 1 ? e.name : std::to_string(e.index);
}

// One row per flame of a .flame file (docs/studio.md, "Flames"), as `ifsfx presets FILE` lists
// them; "maps" counts the xforms.
void add_flame_rows(json& list, const fs::path& folder, const std::string& name) {
  const fs::path path = folder_file(folder, name, true);
  const std::vector<flame::FlameEntry> entries = flame::list_flames(path.string());
  for (const flame::FlameEntry& e : entries) {
    std::string problem = e.problem;
    if (problem.empty() && e.xforms > kMaxMaps)
      problem =
          fmt::format("{}: the studio edits at most {} xforms (got {})", name, kMaxMaps, e.xforms);
    json row = summary_row(name, {.name = e.name, .maps = e.xforms, .problem = problem});
    row["entry"] = flame_selector(entries, e);
    row["flame"] = true;
    list.push_back(std::move(row));
  }
}

}  // namespace

fs::path folder_file(const fs::path& folder, const std::string& name, bool must_exist) {
  if (!plain_name(name))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a plain name in --folder (got '{}')", name));
  const fs::path path = folder / name;
  if (!must_exist) return path;
  std::error_code ec;
  const fs::path real = fs::canonical(path, ec);
  if (ec || !fs::is_regular_file(real))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file in --folder", name));
  if (real.parent_path() != folder)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: leads out of --folder (got {})", name, real.string()));
  return real;
}

std::string lower_extension(const fs::path& name) {
  return lower(name.extension().string());
}

std::vector<std::string> folder_files(const fs::path& folder,
                                      const std::vector<std::string>& extensions) {
  std::vector<std::string> names;
  for (const auto& name : plain_files(folder)) {
    if (std::find(extensions.begin(), extensions.end(), lower_extension(name)) == extensions.end())
      continue;
    try {
      folder_file(folder, name, true);
      names.push_back(name);
    } catch (const Error&) {
      // a link out of the folder, or a name folder_file does not take
    }
  }
  return names;
}

const std::vector<std::string>& movie_extensions() {
  static const std::vector<std::string> extensions{".mp4", ".mkv", ".mov",  ".avi", ".webm",
                                                   ".m4v", ".mpg", ".mpeg", ".ogv", ".wmv"};
  return extensions;
}

bool is_movie_name(const fs::path& name) {
  const auto& known = movie_extensions();
  return std::find(known.begin(), known.end(), lower_extension(name)) != known.end();
}

bool is_image_name(std::string_view name) {
  for (const char* ext : {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr", ".bmp", ".webp"})
    if (ends_with(name, ext)) return true;
  return false;
}

json folder_sources(const fs::path& folder) {
  json list = json::array();
  for (const auto& name : plain_files(folder))
    if (is_image_name(name) && list.size() < kMaxListed) list.push_back(name);
  return list;
}

json folder_presets(const fs::path& folder) {
  json list = json::array();
  for (const auto& name : plain_files(folder)) {
    if (list.size() >= kMaxListed) break;
    const bool toml = ends_with(name, ".toml") && !ends_with(name, ".super.toml");
    const bool fractint = ends_with(name, ".ifs");
    if (!toml && !fractint && !flame_name(name)) continue;
    try {
      if (flame_name(name)) {
        add_flame_rows(list, folder, name);
        continue;
      }
      const fs::path path = folder_file(folder, name, true);
      for (const auto& s : list_presets_in(path.string())) {
        json row = summary_row(name, s);
        if (fractint) row["entry"] = s.name;
        list.push_back(std::move(row));
      }
    } catch (const Error& e) {
      // A file that cannot be read at all (a malformed .toml, a .ifs without entries): one row.
      list.push_back(
          summary_row(name, {.name = fs::path(name).stem().string(), .problem = e.what()}));
    }
  }
  return list;
}

IfsPreset open_folder_preset(const fs::path& folder, const std::string& file,
                             const std::string& entry) {
  const bool toml = ends_with(file, ".toml") && !ends_with(file, ".super.toml");
  const bool fractint = ends_with(file, ".ifs");
  if (!toml && !fractint)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: an IFS preset, .toml or .ifs (got '{}')", file));
  const fs::path path = folder_file(folder, file, true);
  if (toml && !entry.empty())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("entry: only for a Fractint .ifs file (got '{}' for {})", entry, file));
  return load_ifs(fractint ? fmt::format("{}:{}", path.string(), entry) : path.string());
}

flame::Flame open_folder_flame(const fs::path& folder, const std::string& file,
                               const std::string& entry) {
  if (!flame_name(file))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a flame file, .flame or .flam3 (got '{}')", file));
  const fs::path path = folder_file(folder, file, true);
  const flame::Flame f =
      flame::read_flame(entry.empty() ? path.string() : fmt::format("{}:{}", path.string(), entry));
  if (f.xforms.size() > kMaxMaps)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the studio edits at most {} xforms (got {})", file, kMaxMaps,
                            f.xforms.size()));
  return f;
}

bool is_flame_name(std::string_view name) {
  return flame_name(name);
}

std::string colouring_file_name(const std::string& preset_file) {
  const std::string stem =
      ends_with(preset_file, ".toml") ? preset_file.substr(0, preset_file.size() - 5) : preset_file;
  return stem + ".colouring.toml";
}

std::string save_upload(const fs::path& folder, const std::string& name, std::string_view bytes,
                        const fs::path& scratch) {
  folder_file(folder, name, false);  // a plain name
  if (!is_image_name(name))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: an image name (.png, .jpg, .jpeg, .tif, .tiff, .exr, .bmp, "
                            ".webp) (got '{}')",
                            name));
  if (bytes.size() > kMaxUploadBytes)
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: at most {} MiB (got {} bytes)", name,
                                                         kMaxUploadBytes >> 20, bytes.size()));
  // Read back first, from a private file with the same extension: only images enter the folder.
  std::random_device entropy;
  const fs::path probe = scratch / fmt::format("upload-{:08x}{}", entropy(),
                                               lower(fs::path(name).extension().string()));
  write_file(probe, bytes);
  cv::Size size;
  try {
    size = read_image(probe).pixels.size();
  } catch (const Error& e) {
    std::error_code ec;
    fs::remove(probe, ec);
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: not an image the studio reads ({})", name, e.what()));
  }
  std::error_code ec;
  fs::remove(probe, ec);
  if (size.width > kMaxUploadSide || size.height > kMaxUploadSide)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: at most {} pixels a side (got {}x{})", name, kMaxUploadSide,
                            size.width, size.height));
  // A free name: the output policy would replace an existing file, which a drop must not do.
  const fs::path p(name);
  std::string chosen = name;
  for (int k = 2; fs::exists(folder / chosen, ec) || fs::is_symlink(folder / chosen, ec); ++k) {
    if (k > 999) throw Error(ErrorKind::io, fmt::format("{}: no free name in --folder", name));
    chosen = fmt::format("{}-{}{}", p.stem().string(), k, p.extension().string());
  }
  write_file(folder / chosen, bytes);
  return chosen;
}

}  // namespace ifsfx::app
