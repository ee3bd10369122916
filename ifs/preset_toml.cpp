// SPDX-License-Identifier: Apache-2.0
// The native preset format: one IFS per TOML file (the layout is documented in ifs/preset.h).
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "ifs/detail/toml_reader.h"
#include "ifs/detail/toml_writer.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "ifs/utf8.h"

namespace ifsfx {

namespace detail {

// The shortest text that reads back as exactly `x` ({fmt} prints the shortest round-trip
// form), kept a TOML float rather than an integer so that the file reads as coefficients.
std::string toml_number(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".ein") == std::string::npos) s += ".0";
  return s;
}

// A TOML basic string; TOML text is UTF-8, so other bytes are read as Latin-1 (valid_utf8).
std::string toml_string(std::string_view text) {
  const std::string s = valid_utf8(text);
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
        else
          out += c;
    }
  }
  return out + "\"";
}

}  // namespace detail

namespace {

using detail::toml_number;
using detail::toml_string;
using detail::TomlReader;

std::vector<double> read_probabilities(const TomlReader& in, const toml::node& node,
                                       std::size_t map_count) {
  const auto& values = in.array(node, "probabilities");
  if (values.size() != map_count)
    in.fail(ErrorKind::invalid_ifs, node.source(),
            fmt::format("probabilities: one per map is needed (got {} for {} maps)", values.size(),
                        map_count));
  std::vector<double> p;
  double sum = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string what = fmt::format("map {}", i + 1);
    const double x = in.number(values[i], fmt::format("{}: probability", what));
    if (!std::isfinite(x) || x < 0)
      in.fail(ErrorKind::invalid_ifs, values[i].source(),
              fmt::format("{}: probability must be a finite number ≥ 0 (got {})", what, x));
    sum += x;
    p.push_back(x);
  }
  if (!(sum > 0))
    in.fail(ErrorKind::invalid_ifs, node.source(),
            "probabilities: they must not all be zero (got sum 0)");
  return p;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "#rrggbb" or [r, g, b] with components in [0, 1].
Rgb read_colour(const TomlReader& in, const toml::node& node, const std::string& what) {
  if (const auto* s = node.as_string()) {
    const std::string& hex = s->get();
    std::array<int, 6> digits{};
    bool ok = hex.size() == 7 && hex[0] == '#';
    for (std::size_t i = 0; ok && i < 6; ++i) ok = (digits[i] = hex_digit(hex[i + 1])) >= 0;
    if (!ok)
      in.fail(
          ErrorKind::parse, node.source(),
          fmt::format("{}: must be \"#rrggbb\" or [r, g, b] in [0, 1] (got \"{}\")", what, hex));
    auto channel = [&](int i) { return (digits[i] * 16 + digits[i + 1]) / 255.0; };
    return {channel(0), channel(2), channel(4)};
  }
  const auto* rgb = node.as_array();
  if (!rgb || rgb->size() != 3)
    in.fail(ErrorKind::parse, node.source(),
            fmt::format("{}: must be \"#rrggbb\" or [r, g, b] in [0, 1] (got {})", what,
                        rgb ? fmt::format("{} numbers", rgb->size())
                            : std::string(TomlReader::type_name(node))));
  std::array<double, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) {
    c[i] = in.number((*rgb)[i], what);
    if (!(c[i] >= 0 && c[i] <= 1))
      in.fail(ErrorKind::parse, (*rgb)[i].source(),
              fmt::format("{}: components must lie in [0, 1] (got {})", what, c[i]));
  }
  return {c[0], c[1], c[2]};
}

std::vector<Rgb> read_colours(const TomlReader& in, const toml::node& node, std::size_t map_count) {
  const auto& values = in.array(node, "colours");
  if (values.size() != map_count)
    in.fail(ErrorKind::invalid_ifs, node.source(),
            fmt::format("colours: one per map is needed (got {} for {} maps)", values.size(),
                        map_count));
  std::vector<Rgb> colours;
  for (std::size_t i = 0; i < values.size(); ++i)
    colours.push_back(read_colour(in, values[i], fmt::format("map {}: colour", i + 1)));
  return colours;
}

// "#rrggbb" when the colour is exactly what such a string reads back as, else [r, g, b].
std::string toml_colour(const Rgb& c) {
  std::array<long, 3> k{};
  const std::array<double, 3> v{c.r, c.g, c.b};
  bool hex = true;
  for (std::size_t i = 0; i < 3; ++i) {
    k[i] = std::lround(v[i] * 255);
    hex = hex && k[i] >= 0 && k[i] <= 255 && static_cast<double>(k[i]) / 255.0 == v[i];
  }
  if (hex) return fmt::format("\"#{:02x}{:02x}{:02x}\"", k[0], k[1], k[2]);
  return fmt::format("[{}, {}, {}]", toml_number(c.r), toml_number(c.g), toml_number(c.b));
}

}  // namespace

IfsPreset parse_ifs_toml(std::string_view text, const std::string& filename) {
  const TomlReader in(filename);
  const toml::table table = in.parse(text);

  // Check every key first, so that a misspelt "probabilites" is reported rather than silently
  // giving default probabilities.
  in.check_keys(table, {"name", "description", "maps", "probabilities", "colours",
                        "allow_expansive", "seamless"});

  IfsPreset preset;
  preset.origin = filename;
  preset.text = std::string(text);
  preset.ifs.name = std::filesystem::path(filename).stem().string();
  if (const auto* node = table.get("name")) preset.ifs.name = in.string(*node, "name");
  if (const auto* node = table.get("description"))
    preset.description = in.string(*node, "description");

  const auto* maps = table.get("maps");
  if (!maps)
    throw Error(
        ErrorKind::parse,
        fmt::format("{}: maps: an IFS needs a 'maps' array of [a, b, c, d, e, f] (got none)",
                    filename));
  preset.ifs.maps = in.maps(*maps);
  if (const auto* node = table.get("probabilities"))
    preset.ifs.probabilities = read_probabilities(in, *node, preset.ifs.maps.size());
  if (const auto* node = table.get("colours"))
    preset.ifs.colours = read_colours(in, *node, preset.ifs.maps.size());
  if (const auto* node = table.get("allow_expansive"))
    preset.allow_expansive = in.boolean(*node, "allow_expansive");
  if (const auto* node = table.get("seamless")) preset.seamless = in.seamless(*node);
  return preset;
}

std::string to_toml(const Ifs& ifs, const std::string& description) {
  std::string out = fmt::format("name = {}\n", toml_string(ifs.name));
  if (!description.empty()) out += fmt::format("description = {}\n", toml_string(description));
  out += "# x' = a x + b y + e, y' = c x + d y + f\nmaps = [\n  # a, b, c, d, e, f\n";
  for (const auto& m : ifs.maps) {
    out += "  [";
    const auto k = m.coefficients();
    for (std::size_t j = 0; j < k.size(); ++j) out += (j ? ", " : "") + toml_number(k[j]);
    out += "],\n";
  }
  out += "]\n";
  auto list = [&](std::string_view key, const auto& values, auto format) {
    if (values.empty()) return;
    out += fmt::format("{} = [", key);
    for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + format(values[i]);
    out += "]\n";
  };
  list("probabilities", ifs.probabilities, toml_number);
  list("colours", ifs.colours, toml_colour);
  return out;
}

}  // namespace ifsfx
