// SPDX-License-Identifier: Apache-2.0
#include "superifs/superifs_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "ifs/detail/toml_reader.h"
#include "ifs/detail/toml_writer.h"
#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx {

namespace {

using detail::TomlReader;

// An [[ifs]] or [[colouring]] table: maps (a b c d e f each) and optional probabilities.
Ifs read_ifs(const TomlReader& in, const toml::table& table, const std::string& what,
             const ValidateOptions& rules) {
  in.check_keys(table, {"name", "maps", "probabilities"}, what + ": ");
  Ifs f;
  if (const auto* n = table.get("name")) f.name = in.string(*n, what + " name");
  const auto* maps = table.get("maps");
  if (!maps)
    in.fail(ErrorKind::parse, table.source(), what + ": needs maps = [[a, b, c, d, e, f], ...]");
  f.maps = in.maps(*maps, what);
  if (const auto* p = table.get("probabilities"))
    f.probabilities = in.numbers(*p, what + " probabilities");
  validate(f, in.at(table.source()) + ": " + what, rules);
  return f;
}

// The tables of an array of tables [[KEY]] (none when the key is absent).
std::vector<const toml::table*> read_tables(const TomlReader& in, const toml::table& root,
                                            std::string_view key) {
  std::vector<const toml::table*> out;
  const auto* node = root.get(key);
  if (!node) return out;
  const auto* array = node->as_array();
  if (!array)
    in.fail(ErrorKind::parse, node->source(),
            fmt::format("{}: must be a list of tables [[{}]] (got {})", key, key,
                        TomlReader::type_name(*node)));
  for (const auto& item : *array) {
    const auto* table = item.as_table();
    if (!table)
      in.fail(ErrorKind::parse, item.source(),
              fmt::format("{}: every entry must be a table [[{}]] (got {})", key, key,
                          TomlReader::type_name(item)));
    out.push_back(table);
  }
  return out;
}

}  // namespace

SuperIfsPreset parse_superifs_toml(std::string_view text, const std::string& filename) {
  const TomlReader read(filename);
  const toml::table root = read.parse(text);
  read.check_keys(
      root, {"name", "description", "probabilities", "view", "ifs", "colouring", "seamless"}, "");
  SuperIfsPreset preset;
  preset.text = std::string(text);
  SuperIfs& super = preset.super;
  if (const auto* n = root.get("name")) super.name = read.string(*n, "name");
  if (const auto* d = root.get("description")) preset.description = read.string(*d, "description");

  const auto ifs_tables = read_tables(read, root, "ifs");
  if (ifs_tables.empty())
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}:1: a superIFS needs at least one [[ifs]] table (got 0)", filename));
  for (std::size_t n = 0; n < ifs_tables.size(); ++n) {
    const std::string what = fmt::format("IFS {}", n + 1);
    super.ifs.push_back(read_ifs(read, *ifs_tables[n], what, {}));
    if (super.ifs[n].size() != super.ifs[0].size())
      read.fail(ErrorKind::invalid_ifs, ifs_tables[n]->source(),
                fmt::format("{}: every IFS needs the same number of maps as IFS 1 (got {} for {})",
                            what, super.ifs[n].size(), super.ifs[0].size()));
  }
  if (const auto* p = root.get("probabilities")) {
    super.probabilities = read.numbers(*p, "probabilities");
    if (super.probabilities.size() != super.size())
      read.fail(ErrorKind::invalid_ifs, p->source(),
                fmt::format("probabilities: one per [[ifs]] is needed (got {} for {} IFSs)",
                            super.probabilities.size(), super.size()));
  }
  if (const auto* v = root.get("view")) {
    const auto box = read.numbers(*v, "view");
    if (box.size() != 4)
      read.fail(ErrorKind::parse, v->source(),
                fmt::format("view: needs 4 numbers x0, y0, x1, y1 (got {})", box.size()));
    super.view = Box{box[0], box[1], box[2], box[3]};
  }
  const auto colouring_tables = read_tables(read, root, "colouring");
  for (std::size_t n = 0; n < colouring_tables.size(); ++n) {
    const std::string what = fmt::format("colouring {}", n + 1);
    // Colourings may use the strip tilings, factor 1 per map but contracting in pairs.
    super.colouring.push_back(
        read_ifs(read, *colouring_tables[n], what, {.allow_expansive = true}));
    if (super.colouring[n].size() != super.maps())
      read.fail(ErrorKind::invalid_ifs, colouring_tables[n]->source(),
                fmt::format("{}: needs as many maps as the IFSs (got {} for {})", what,
                            super.colouring[n].size(), super.maps()));
  }
  if (const auto* t = root.get("seamless")) preset.seamless = read.seamless(*t);
  // The remaining rules (singular maps, view, colouring count) have no better line than the file.
  validate(super, filename);
  return preset;
}

namespace {

using detail::toml_number;
using detail::toml_string;

std::string number_list(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + toml_number(values[i]);
  return out + "]";
}

// An [[ifs]] or [[colouring]] table.
std::string ifs_table(std::string_view key, const Ifs& f) {
  std::string out = fmt::format("\n[[{}]]\n", key);
  if (!f.name.empty()) out += fmt::format("name = {}\n", toml_string(f.name));
  out += "maps = [\n  # a, b, c, d, e, f\n";
  for (const auto& m : f.maps) {
    const auto k = m.coefficients();
    out += "  " + number_list({k.begin(), k.end()}) + ",\n";
  }
  out += "]\n";
  if (!f.probabilities.empty())
    out += fmt::format("probabilities = {}\n", number_list(f.probabilities));
  return out;
}

}  // namespace

std::string to_toml(const SuperIfs& super, const std::string& description) {
  std::string out = fmt::format("name = {}\n", toml_string(super.name));
  if (!description.empty()) out += fmt::format("description = {}\n", toml_string(description));
  if (!super.probabilities.empty())
    out += fmt::format("probabilities = {}\n", number_list(super.probabilities));
  if (super.view) {
    const Box& v = *super.view;
    out += fmt::format("view = {}\n", number_list({v.x0, v.y0, v.x1, v.y1}));
  }
  for (const Ifs& f : super.ifs) out += ifs_table("ifs", f);
  for (const Ifs& g : super.colouring) out += ifs_table("colouring", g);
  return out;
}

namespace {

std::string stem_of(std::string_view file_name) {
  return std::string(file_name.substr(0, file_name.size() - superifs_extension.size()));
}

bool is_superifs_file(std::string_view file_name) {
  return file_name.size() > superifs_extension.size() && file_name.ends_with(superifs_extension);
}

}  // namespace

SuperIfsPreset load_superifs(const std::string& spec) {
  for (const auto& file : shipped_files()) {
    if (is_superifs_file(file.name) && stem_of(file.name) == spec) {
      auto preset = parse_superifs_toml(file.text, std::string(file.name));
      preset.origin = fmt::format("shipped:{}", file.name);
      return preset;
    }
  }
  const std::filesystem::path path(spec);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::string names;
    for (const auto& s : list_shipped_superifs())
      names += fmt::format("{}{}", names.empty() ? "" : ", ", s.name);
    throw Error(ErrorKind::not_found,
                fmt::format("{}: no such superIFS preset or file (shipped: {})", spec, names));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw Error(ErrorKind::io, fmt::format("{}: cannot read the file", spec));
  auto preset = parse_superifs_toml(text.str(), spec);
  preset.origin = spec;
  return preset;
}

std::vector<SuperIfsSummary> list_shipped_superifs() {
  std::vector<SuperIfsSummary> out;
  for (const auto& file : shipped_files()) {
    if (!is_superifs_file(file.name)) continue;
    const auto preset = parse_superifs_toml(file.text, std::string(file.name));
    out.push_back({stem_of(file.name), preset.super.size(), preset.super.maps(), preset.description,
                   preset.seamless.has_value()});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

}  // namespace ifsfx
