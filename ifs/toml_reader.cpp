// SPDX-License-Identifier: Apache-2.0
#include "ifs/detail/toml_reader.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace ifsfx::detail {

std::string TomlReader::at(const toml::source_region& where) const {
  return fmt::format("{}:{}", filename_, where.begin.line);
}

void TomlReader::fail(ErrorKind kind, const toml::source_region& where,
                      const std::string& what) const {
  throw Error(kind, fmt::format("{}: {}", at(where), what));
}

namespace {

// toml++ builds a dotted key's tables by recursion, one level per part: a key of tens of
// thousands of parts overflows the stack before any error can be raised. Presets need a few parts
// and levels; these bounds are far above that and far below what the stack holds.
constexpr int kMaxKeyParts = 32;
constexpr int kMaxNesting = 32;  // arrays and inline tables inside each other
constexpr std::size_t kMaxBytes = 16u << 20;

bool bare_key_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

}  // namespace

void TomlReader::check_shape(std::string_view text) const {
  if (text.size() > kMaxBytes)
    throw Error(ErrorKind::parse,
                fmt::format("{}: larger than any preset (got {} bytes; at most {} MiB)", filename_,
                            text.size(), kMaxBytes >> 20));
  // One pass over the text: strings and comments skipped, runs of key parts joined by dots
  // counted ("a.b.c" and "1.5" alike: only keys make long runs), brackets and braces nested.
  int line = 1, parts = 0, nesting = 0;
  bool dot = false;  // a dot ended the last run: the next part continues it
  auto part = [&] {
    parts = dot ? parts + 1 : 1;
    dot = false;
    if (parts > kMaxKeyParts)
      throw Error(ErrorKind::parse, fmt::format("{}:{}: a dotted key of more than {} parts "
                                                "(a preset needs a few)",
                                                filename_, line, kMaxKeyParts));
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (c == '#') {  // a comment, to the end of the line
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      parts = 0, dot = false;
    } else if (c == '"' || c == '\'') {  // a string or a quoted key part
      const bool multi = text.substr(i, 3) == std::string(3, c);
      const std::string_view close = multi ? text.substr(i, 3) : text.substr(i, 1);
      i += close.size();
      while (i < text.size() && text.substr(i, close.size()) != close) {
        if (text[i] == '\n') ++line;
        if (c == '"' && text[i] == '\\') ++i;  // an escape in a basic string
        ++i;
      }
      i += close.size() - 1;
      part();
    } else if (bare_key_char(c)) {
      while (i + 1 < text.size() && bare_key_char(text[i + 1])) ++i;
      part();
    } else if (c == '.') {
      dot = parts > 0;
    } else if (c != ' ' && c != '\t') {
      parts = 0, dot = false;
      if (c == '[' || c == '{') {
        if (++nesting > kMaxNesting)
          throw Error(ErrorKind::parse, fmt::format("{}:{}: arrays and tables nested more than {} "
                                                    "deep (a preset needs a few)",
                                                    filename_, line, kMaxNesting));
      } else if (c == ']' || c == '}') {
        nesting = std::max(0, nesting - 1);
      }
    }
  }
}

toml::table TomlReader::parse(std::string_view text) const {
  check_shape(text);
  try {
    return toml::parse(text, filename_);
  } catch (const toml::parse_error& e) {
    fail(ErrorKind::parse, e.source(), std::string(e.description()));
  }
}

void TomlReader::check_keys(const toml::table& table,
                            std::initializer_list<std::string_view> allowed,
                            const std::string& context) const {
  for (const auto& [key, value] : table) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
    std::string names;
    for (const std::string_view a : allowed)
      names += fmt::format("{}{}", names.empty() ? "" : ", ", a);
    fail(ErrorKind::parse, key.source(),
         fmt::format("{}unknown key '{}' (known: {})", context, key.str(), names));
  }
}

std::string TomlReader::string(const toml::node& node, const std::string& what) const {
  if (const auto* s = node.as_string()) return s->get();
  fail(ErrorKind::parse, node.source(),
       fmt::format("{}: must be a string (got {})", what, type_name(node)));
}

bool TomlReader::boolean(const toml::node& node, const std::string& what) const {
  if (const auto* b = node.as_boolean()) return b->get();
  fail(ErrorKind::parse, node.source(),
       fmt::format("{}: must be true or false (got {})", what, type_name(node)));
}

double TomlReader::number(const toml::node& node, const std::string& what) const {
  if (const auto* x = node.as_floating_point()) return x->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  fail(ErrorKind::parse, node.source(),
       fmt::format("{}: must be a number (got {})", what, type_name(node)));
}

const toml::array& TomlReader::array(const toml::node& node, const std::string& what) const {
  if (const auto* a = node.as_array()) return *a;
  fail(ErrorKind::parse, node.source(),
       fmt::format("{}: must be an array (got {})", what, type_name(node)));
}

std::vector<double> TomlReader::numbers(const toml::node& node, const std::string& what) const {
  std::vector<double> out;
  for (const toml::node& item : array(node, what)) out.push_back(number(item, what));
  return out;
}

SeamlessTile TomlReader::seamless(const toml::node& node) const {
  const toml::table* table = node.as_table();
  if (!table)
    fail(ErrorKind::parse, node.source(),
         fmt::format("seamless: must be a table with view and offset (got {})", type_name(node)));
  check_keys(*table, {"view", "offset"}, "seamless: ");
  SeamlessTile tile;
  if (const auto* v = table->get("view")) {
    const auto box = numbers(*v, "seamless: view");
    if (box.size() != 4)
      fail(ErrorKind::parse, v->source(),
           fmt::format("seamless: view: needs 4 numbers x0, y0, x1, y1 (got {})", box.size()));
    if (!(std::isfinite(box[0]) && std::isfinite(box[1]) && std::isfinite(box[2]) &&
          std::isfinite(box[3]) && box[0] < box[2] && box[1] < box[3]))
      fail(ErrorKind::parse, v->source(),
           fmt::format("seamless: view: needs finite x0 < x1 and y0 < y1 (got {}, {}, {}, {})",
                       box[0], box[1], box[2], box[3]));
    tile.view = Box{box[0], box[1], box[2], box[3]};
  }
  if (const auto* o = table->get("offset")) {
    const auto offset = numbers(*o, "seamless: offset");
    if (offset.size() != 2 || !(offset[0] >= 0 && offset[0] < 1 && offset[1] >= 0 && offset[1] < 1))
      fail(ErrorKind::parse, o->source(),
           fmt::format("seamless: offset: needs 2 fractions of the tile in [0, 1) (got {})",
                       fmt::join(offset, ", ")));
    tile.offset = {offset[0], offset[1]};
  }
  return tile;
}

std::vector<AffineMap> TomlReader::maps(const toml::node& node, const std::string& prefix) const {
  const std::string lead = prefix.empty() ? "" : prefix + " ";
  const toml::array& rows = array(node, lead + "maps");
  if (rows.empty())
    fail(ErrorKind::invalid_ifs, node.source(),
         fmt::format("{}maps: an IFS needs at least one map (got 0)", lead));
  std::vector<AffineMap> maps;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string what = fmt::format("{}map {}", lead, i + 1);
    const toml::array& row = array(rows[i], what);
    if (row.size() != 6)
      fail(ErrorKind::parse, rows[i].source(),
           fmt::format("{}: needs 6 numbers a b c d e f (got {})", what, row.size()));
    std::array<double, 6> k{};
    for (std::size_t j = 0; j < 6; ++j) {
      k[j] = number(row[j], what);
      if (!std::isfinite(k[j]))
        fail(ErrorKind::invalid_ifs, row[j].source(),
             fmt::format("{}: coefficients must be finite numbers (got {})", what, k[j]));
    }
    maps.push_back(AffineMap::from_coefficients(k));
  }
  return maps;
}

std::string_view TomlReader::type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time:
      return "a date or time";
    default:
      return "nothing";
  }
}

}  // namespace ifsfx::detail
