// SPDX-License-Identifier: Apache-2.0
// The files `ifsfx studio` reads and writes: only in its --folder, by plain names (one path
// component, no hidden file, no `..`, no link that leads out of the folder). What the folder
// offers the page: its images (colour-stealing sources), its presets (every .toml and every entry
// of every Fractint .ifs file, the unusable ones with the reason), and images dropped on the page,
// saved under the output policy (docs/studio.md).
//
//   const fs::path photo = folder_file(folder, "photo.jpg", true);   // or Error
//   const nlohmann::json list = folder_presets(folder);
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "flame/flame.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"

namespace ifsfx::app {

// The largest image accepted from the page, in bytes and pixels a side.
inline constexpr std::size_t kMaxUploadBytes = 32u << 20;
inline constexpr int kMaxUploadSide = 8192;

// `name` in `folder` (which is canonical). Throws Error{invalid_argument} "file: a plain name in
// --folder (got 'NAME')" for anything but a plain name; with `must_exist`, Error{not_found} when
// there is no such regular file and Error{invalid_argument} when it is a link that leads out of
// the folder. Returns the file (links followed) or, without `must_exist`, folder / name.
std::filesystem::path folder_file(const std::filesystem::path& folder, const std::string& name,
                                  bool must_exist);

// Whether `name` ends in an image extension the studio takes as a source (.png, .jpg, .jpeg,
// .tif, .tiff, .exr, .bmp, .webp; any case).
bool is_image_name(std::string_view name);

// The movie extensions the studio offers (lower case, with the dot: ".mp4", ".mkv", ...), and
// whether `name` has one (any case).
const std::vector<std::string>& movie_extensions();
bool is_movie_name(const std::filesystem::path& name);

// The extension of `name`, lower case, with its dot (".png").
std::string lower_extension(const std::filesystem::path& name);

// The plain names of `folder`'s files that folder_file(folder, name, true) opens (no link that
// leads out of the folder) whose extension (lower_extension) is one of `extensions`, sorted.
std::vector<std::string> folder_files(const std::filesystem::path& folder,
                                      const std::vector<std::string>& extensions);

// The images of `folder` by name, sorted (hidden files and folders left out).
nlohmann::json folder_sources(const std::filesystem::path& folder);

// The presets of `folder`: [{"file", "entry" (Fractint and flame files), "name", "maps",
// "contraction", "description", "problem", "flame" (flames: true)}], one per .toml file (superIFS
// files, *.super.toml, left out), one per entry of each .ifs file and one per flame of each
// .flame or .flam3 file (its "entry" picks it: its name, or its index where the name is empty or
// taken twice; "maps" counts its xforms), sorted by file; "problem" is why it cannot be opened
// (as `ifsfx presets FILE` says it), empty when it can. At most 1000 rows.
nlohmann::json folder_presets(const std::filesystem::path& folder);

// A preset of `folder`: the .toml `file`, or the entry `entry` of the .ifs `file` (its first when
// empty), loaded as `ifsfx render FILE[:ENTRY]` loads it. Throws what folder_file and load_ifs
// throw.
IfsPreset open_folder_preset(const std::filesystem::path& folder, const std::string& file,
                             const std::string& entry);

// Whether `name` ends in .flame or .flam3 (any case).
bool is_flame_name(std::string_view name);

// The flame `entry` (a name or an index; may be empty for a file of one flame) of the flame file
// `file` of `folder`, read as `ifsfx render FILE.flame:ENTRY` reads it. Throws what folder_file
// and read_flame throw, and Error{invalid_argument} for another extension or more than kMaxMaps
// xforms.
flame::Flame open_folder_flame(const std::filesystem::path& folder, const std::string& file,
                               const std::string& entry);

// The file a preset NAME.toml keeps its colouring IFS in: NAME.colouring.toml.
std::string colouring_file_name(const std::string& preset_file);

// Saves an image dropped on the page as `name` in `folder` under the output policy, or as
// STEM-2.EXT, STEM-3.EXT ... when `name` is taken: never over an existing file. The bytes are
// first read back as an image (from a file in `scratch`): Error{invalid_argument} for a name
// without an image extension or bytes that are no readable image, Error{invalid_argument} for a
// picture over kMaxUploadSide a side. Returns the name it was saved under.
// The caller serialises calls for one folder (a free name must stay free until written).
std::string save_upload(const std::filesystem::path& folder, const std::string& name,
                        std::string_view bytes, const std::filesystem::path& scratch);

}  // namespace ifsfx::app
