// SPDX-License-Identifier: Apache-2.0
#include "flame/flame_file.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "flame/detail/flame_xml.h"
#include "ifs/error.h"

namespace ifsfx::flame {
namespace {

using detail::Where;

bool has_flame_extension(std::string_view path) {
  for (std::string_view ext : {".flame", ".flam3"})
    if (path.size() > ext.size() && path.ends_with(ext)) return true;
  return false;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorKind::not_found, fmt::format("{}: no such flame file", path));
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(ErrorKind::io, fmt::format("{}: could not be read", path));
  return text.str();
}

// The document's <flame> elements; throws for text that is not XML or holds none.
std::vector<pugi::xml_node> load(pugi::xml_document& doc, std::string_view xml,
                                 const std::string& where) {
  const pugi::xml_parse_result r =
      doc.load_buffer(xml.data(), xml.size(), pugi::parse_default | pugi::parse_fragment);
  if (!r) {
    const std::size_t off = std::min<std::size_t>(static_cast<std::size_t>(r.offset), xml.size());
    const auto line =
        1 + std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(off), '\n');
    throw Error(ErrorKind::parse,
                fmt::format("{}:{}: not flame XML: {}", where, line, r.description()));
  }
  std::vector<pugi::xml_node> flames = detail::flame_nodes(doc);
  if (flames.empty())
    throw Error(ErrorKind::parse,
                fmt::format("{}: a flame file needs a <flame> element (got none)", where));
  return flames;
}

Where where_of(const std::string& file, const pugi::xml_node& f, std::size_t index) {
  const std::string name = f.attribute("name").value();
  return {file, name.empty() ? fmt::format("#{}", index) : name};
}

std::string names_of(const std::vector<pugi::xml_node>& flames) {
  std::string s;
  for (std::size_t i = 0; i < flames.size() && i < 8; ++i) {
    const std::string name = flames[i].attribute("name").value();
    s += fmt::format("{}{}:{}", i ? ", " : "", i, name.empty() ? "(unnamed)" : name);
  }
  if (flames.size() > 8) s += fmt::format(", ... ({} flames)", flames.size());
  return s;
}

}  // namespace

std::vector<Flame> parse_flames(std::string_view xml, const std::string& where,
                                const FlameReadOptions& options) {
  pugi::xml_document doc;
  const std::vector<pugi::xml_node> nodes = load(doc, xml, where);
  std::vector<Flame> out;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    out.push_back(detail::parse_flame(where_of(where, nodes[i], i), nodes[i], options));
  return out;
}

FlameSpec split_flame_spec(const std::string& spec) {
  for (std::string_view ext : {".flame:", ".flam3:"}) {
    const std::size_t at = spec.rfind(ext);
    if (at != std::string::npos && at > 0)
      return {spec.substr(0, at + ext.size() - 1), spec.substr(at + ext.size())};
  }
  return {spec, ""};
}

bool is_flame_spec(const std::string& spec) {
  return has_flame_extension(split_flame_spec(spec).path);
}

std::vector<Flame> read_flames(const std::string& path, const FlameReadOptions& options) {
  return parse_flames(read_text(path), path, options);
}

Flame read_flame(const std::string& spec, const FlameReadOptions& options) {
  const FlameSpec s = split_flame_spec(spec);
  const std::string xml = read_text(s.path);
  pugi::xml_document doc;
  const std::vector<pugi::xml_node> nodes = load(doc, xml, s.path);
  std::optional<std::size_t> pick;
  if (s.selector.empty()) {
    if (nodes.size() != 1)
      throw Error(ErrorKind::not_found,
                  fmt::format("{}: holds {} flames: pick one as {}:NAME or {}:INDEX ({})", s.path,
                              nodes.size(), s.path, s.path, names_of(nodes)));
    pick = 0;
  }
  for (std::size_t i = 0; !pick && i < nodes.size(); ++i)
    if (s.selector == nodes[i].attribute("name").value()) pick = i;
  if (!pick && s.selector.find_first_not_of("0123456789") == std::string::npos &&
      s.selector.size() < 10) {
    const std::size_t i = std::stoul(s.selector);
    if (i < nodes.size()) pick = i;
  }
  if (!pick)
    throw Error(ErrorKind::not_found,
                fmt::format("{}: no flame \"{}\" (got {})", s.path, s.selector, names_of(nodes)));
  return detail::parse_flame(where_of(s.path, nodes[*pick], *pick), nodes[*pick], options);
}

std::vector<FlameEntry> list_flames(const std::string& path, const FlameReadOptions& options) {
  const std::string xml = read_text(path);
  pugi::xml_document doc;
  const std::vector<pugi::xml_node> nodes = load(doc, xml, path);
  std::vector<FlameEntry> out;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    FlameEntry e{.name = nodes[i].attribute("name").value(), .index = i};
    try {
      e.xforms = detail::parse_flame(where_of(path, nodes[i], i), nodes[i], options).xforms.size();
    } catch (const Error& err) {
      e.problem = err.what();
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace ifsfx::flame
