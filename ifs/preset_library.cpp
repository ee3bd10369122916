// SPDX-License-Identifier: Apache-2.0
// Finding a preset: a shipped name, a path to a .toml or .ifs file, or FILE.ifs:NAME.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "ifs/error.h"
#include "ifs/fractaldb_csv.h"
#include "ifs/fractint.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"

namespace ifsfx {
namespace {

namespace fs = std::filesystem;

bool ends_with(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<long>(suffix.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

bool same_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && ends_with(a, b);
}

// superIFS presets (*.super.toml) share the folder but are not IFSs.
bool is_super(std::string_view file) {
  return ends_with(file, ".super.toml");
}
bool is_ifs_toml(std::string_view file) {
  return ends_with(file, ".toml") && !is_super(file);
}
bool is_fractint(std::string_view file) {
  return ends_with(file, ".ifs");
}

std::string stem(std::string_view file) {
  return fs::path(file).stem().string();
}

// Levenshtein distance, to suggest the name the user probably meant.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (std::tolower(a[i - 1]) != std::tolower(b[j - 1]));
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

const ShippedFile* find_shipped_file(std::string_view name) {
  for (const auto& file : shipped_files())
    if (file.name == name) return &file;
  return nullptr;
}

std::string shipped_origin(std::string_view file) {
  return fmt::format("shipped:{}", file);
}

// Every shipped IFS preset in listing order: the .toml files, then the entries of the .ifs files.
std::vector<IfsPreset> all_shipped() {
  std::vector<IfsPreset> presets;
  for (const auto& file : shipped_files()) {
    if (!is_ifs_toml(file.name)) continue;
    IfsPreset preset = parse_ifs_toml(file.text, std::string(file.name));
    preset.origin = shipped_origin(file.name);
    presets.push_back(std::move(preset));
  }
  for (const auto& file : shipped_files()) {
    if (!is_fractint(file.name)) continue;
    for (auto& entry : parse_fractint(file.text, std::string(file.name))) {
      entry.origin = shipped_origin(entry.origin);
      presets.push_back(std::move(entry));
    }
  }
  return presets;
}

// The name a shipped preset is called by: a .toml file's stem, or a Fractint entry's name.
std::string shipped_name(const IfsPreset& preset) {
  constexpr std::string_view prefix = "shipped:";
  const std::string_view origin = std::string_view(preset.origin).substr(prefix.size());
  if (ends_with(origin, ".toml")) return stem(origin);
  return preset.ifs.name;
}

IfsPreset find_shipped(const std::string& name) {
  auto presets = all_shipped();
  for (int pass = 0; pass < 2; ++pass)  // exact first, then ignoring case as Fractint does
    for (auto& preset : presets) {
      const std::string candidate = shipped_name(preset);
      if (pass == 0 ? candidate == name : same_ignoring_case(candidate, name))
        return std::move(preset);
    }
  std::optional<std::string> closest;
  std::size_t best = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const auto& preset : presets) {
    const std::string candidate = shipped_name(preset);
    const std::size_t d = edit_distance(name, candidate);
    if (d < best) best = d, closest = candidate;
  }
  throw Error(ErrorKind::not_found,
              closest ? fmt::format("unknown preset '{}': did you mean '{}'? (see `ifsfx presets`)",
                                    name, *closest)
                      : fmt::format("unknown preset '{}' (see `ifsfx presets`)", name));
}

struct SourceText {
  std::string text;
  std::string filename;  // how errors name it
  std::string origin;    // what IfsPreset::origin says
};

// A file on disk, or else (for a bare file name) a shipped file of that name.
SourceText read_source(const std::string& path) {
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (fs::is_directory(path, ec))
      throw Error(ErrorKind::io, fmt::format("{}: cannot read (got a folder)", path));
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    if (in) text << in.rdbuf();
    if (!in || in.bad())
      throw Error(ErrorKind::io, fmt::format("{}: cannot read ({})", path, std::strerror(errno)));
    return {text.str(), path, path};
  }
  if (fs::path(path).filename() == path)
    if (const auto* shipped = find_shipped_file(path))
      return {std::string(shipped->text), path, shipped_origin(path)};
  throw Error(ErrorKind::not_found, fmt::format("{}: no such file", path));
}

// The entries of a Fractint file, each usable one named by where it comes from (FILE:NAME).
// Throws Error{parse} for a file without any.
std::vector<detail::FractintEntry> entries_of(const SourceText& source) {
  auto entries = detail::read_fractint_entries(source.text, source.filename);
  if (entries.empty())
    throw Error(ErrorKind::parse,
                fmt::format("{}: no entries (got a Fractint file without any)", source.filename));
  for (auto& entry : entries)
    if (entry.preset) entry.preset->origin = fmt::format("{}:{}", source.origin, entry.name);
  return entries;
}

// One entry of a Fractint file: the named one, or the first. Only the entry picked has to be
// usable, so a 2-D entry loads from a file that also holds (3D) ones.
IfsPreset pick_entry(const SourceText& source, const std::string& name) {
  auto entries = entries_of(source);
  detail::FractintEntry* picked = name.empty() ? &entries.front() : nullptr;
  for (int pass = 0; pass < 2 && !picked; ++pass)
    for (auto& entry : entries)
      if (pass == 0 ? entry.name == name : same_ignoring_case(entry.name, name)) {
        picked = &entry;
        break;
      }
  if (!picked) {
    std::string names;
    for (const auto& entry : entries) names += (names.empty() ? "" : ", ") + entry.name;
    throw Error(ErrorKind::not_found,
                fmt::format("{}: no entry '{}' (entries: {})", source.filename, name, names));
  }
  if (picked->error) throw *picked->error;
  return std::move(*picked->preset);
}

// A FractalDB category CSV as a preset (ifs/fractaldb_csv.h): the file's own checks, which
// refuse a row set that does not contract on average.
IfsPreset fractaldb_category(const SourceText& source) {
  const fractaldb::Category category = fractaldb::parse_category(source.text, source.filename);
  IfsPreset preset;
  preset.ifs = category.ifs();
  preset.description = fmt::format("FractalDB category {}", category.name);
  preset.origin = source.origin;
  preset.text = source.text;
  preset.format = PresetFormat::fractaldb;
  return preset;
}

IfsPreset resolve(const std::string& spec) {
  if (spec.empty())
    throw Error(ErrorKind::invalid_argument,
                "preset: a preset name or a path is needed (got nothing)");
  // FILE.ifs:NAME — one entry of a Fractint file.
  if (const auto colon = spec.rfind(':'); colon != std::string::npos) {
    const std::string file = spec.substr(0, colon);
    if (is_fractint(file)) return pick_entry(read_source(file), spec.substr(colon + 1));
  }
  if (is_fractint(spec)) return pick_entry(read_source(spec), "");
  if (is_super(spec))
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: a superIFS preset, not an IFS (got a .super.toml file)", spec));
  if (ends_with(spec, ".toml")) {
    const SourceText source = read_source(spec);
    IfsPreset preset = parse_ifs_toml(source.text, source.filename);
    preset.origin = source.origin;
    return preset;
  }
  if (ends_with(spec, ".csv")) return fractaldb_category(read_source(spec));
  if (spec.find('/') != std::string::npos)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: preset files end in .toml, .ifs or .csv (a FractalDB category) "
                            "(got none of them)",
                            spec));
  return find_shipped(spec);
}

}  // namespace

std::vector<PresetSummary> list_shipped_presets() {
  std::vector<PresetSummary> list;
  for (const auto& preset : all_shipped())
    list.push_back({shipped_name(preset),
                    preset.ifs.size(),
                    preset.ifs.contraction(),
                    preset.description,
                    {},
                    preset.seamless.has_value()});
  return list;
}

namespace {

// Fractint and FractalDB render IFSs that contract only on average (a map of factor ≥ 1 among
// contracting ones); their files are taken so, with a warning (load_ifs).
bool contracts_on_average(PresetFormat format) {
  return format == PresetFormat::fractint || format == PresetFormat::fractaldb;
}

// Fractint validates an entry as we do, when it is picked: an IFS that contracts on average.
void validate_entry(const IfsPreset& preset, const ValidateOptions& options) {
  ValidateOptions relaxed = options;
  relaxed.allow_expansive =
      options.allow_expansive || preset.allow_expansive || contracts_on_average(preset.format);
  validate(preset.ifs, preset.origin, relaxed);
}

// Why a Fractint entry cannot be used, as load_ifs("FILE.ifs:NAME") says it; empty when it can.
std::string entry_problem(const detail::FractintEntry& entry, const ValidateOptions& options) {
  if (entry.error) return entry.error->what();
  try {
    validate_entry(*entry.preset, options);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

// For a Fractint file named without an entry whose first entry cannot be used (artists' files
// often open with a `_README {...}` block of notes): which entries there are, and the first
// usable one, so that the message says what to type instead.
std::string other_entries_hint(const std::string& path, const ValidateOptions& options) {
  try {
    const auto entries = entries_of(read_source(path));
    if (entries.size() < 2) return {};
    for (std::size_t i = 1; i < entries.size(); ++i) {
      if (!entry_problem(entries[i], options).empty()) continue;
      return fmt::format(
          " (the first of the file's {} entries; name one as FILE.ifs:NAME, e.g. "
          "{}:{})",
          entries.size(), path, entries[i].name);
    }
    return fmt::format(" (the first of the file's {} entries, none of which is usable)",
                       entries.size());
  } catch (const Error&) {
    return {};
  }
}

}  // namespace

std::vector<PresetSummary> list_presets_in(const std::string& path,
                                           const ValidateOptions& options) {
  std::vector<PresetSummary> list;
  if (!is_fractint(path)) {
    const IfsPreset p = load_ifs(path, options);
    list.push_back(
        {p.ifs.name, p.ifs.size(), p.ifs.contraction(), p.description, {}, p.seamless.has_value()});
    return list;
  }
  for (const auto& entry : entries_of(read_source(path))) {
    PresetSummary s{entry.name, 0, 0, {}, entry_problem(entry, options)};
    if (entry.preset) {
      s.maps = entry.preset->ifs.size();
      s.contraction = entry.preset->ifs.contraction();
      s.description = entry.preset->description;
    }
    list.push_back(std::move(s));
  }
  return list;
}

IfsPreset load_ifs(const std::string& spec, const ValidateOptions& options) {
  IfsPreset preset;
  try {
    preset = resolve(spec);
    validate_entry(preset, options);
  } catch (const Error& e) {
    if (!is_fractint(spec) || e.kind() == ErrorKind::not_found || e.kind() == ErrorKind::io) throw;
    const std::string hint = other_entries_hint(spec, options);
    if (hint.empty()) throw;
    throw Error(e.kind(), e.what() + hint);
  }
  // Fractint renders IFSs that contract only on average; so do we, saying so once, unless the
  // caller or the file already accepted that.
  const bool allowed = options.allow_expansive || preset.allow_expansive;
  if (contracts_on_average(preset.format) && !allowed) {
    std::vector<std::string> maps, factors;
    for (std::size_t i = 0; i < preset.ifs.size(); ++i)
      if (const double s = preset.ifs.maps[i].contraction(); s >= 1) {
        maps.push_back(std::to_string(i + 1));
        factors.push_back(fmt::format("{:.4g}", s));
      }
    if (!maps.empty())
      preset.warnings.push_back(fmt::format(
          "{}: {} {} {} not contract (factor{} {}); accepted as {} renders it, since the IFS "
          "contracts on average (mean log factor {:.3g})",
          preset.origin, maps.size() == 1 ? "map" : "maps", fmt::join(maps, ", "),
          maps.size() == 1 ? "does" : "do", maps.size() == 1 ? "" : "s", fmt::join(factors, ", "),
          preset.format == PresetFormat::fractint ? "Fractint" : "FractalDB",
          mean_log_contraction(preset.ifs)));
  }
  return preset;
}

Ifs load_colouring(const std::string& spec, const Ifs& F, const std::string& what) {
  if (spec.empty()) return default_colouring(F.size());
  Ifs G = fit_to_unit_square(load_ifs(spec, {.allow_expansive = true}).ifs);
  if (G.size() != F.size())
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}: {} must have as many maps as {} (got {} for {})", what, spec,
                            F.name, G.size(), F.size()));
  return G;
}

}  // namespace ifsfx
