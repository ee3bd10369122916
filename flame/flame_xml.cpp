// SPDX-License-Identifier: Apache-2.0
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "flame/detail/flame_xml.h"
#include "ifs/error.h"

namespace ifsfx::flame::detail {
namespace {

// Attribute text in messages: enough to recognise, never a whole palette.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 60;
  std::string s(text.substr(0, kMax));
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (text.size() > kMax) s += "...";
  return s;
}

bool space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',';
}

}  // namespace

void Where::fail(std::string_view what, std::string_view rule, std::string_view got) const {
  throw Error(ErrorKind::parse, fmt::format("{}: flame \"{}\": {}: {} (got \"{}\")", file, flame,
                                            what, rule, shown(got)));
}

void Where::fail(std::string_view what, std::string_view rule) const {
  throw Error(ErrorKind::parse, fmt::format("{}: flame \"{}\": {}: {}", file, flame, what, rule));
}

double number(const Where& at, std::string_view what, std::string_view text) {
  std::size_t b = 0, e = text.size();
  while (b < e && space(text[b])) ++b;
  while (e > b && space(text[e - 1])) --e;
  std::string_view t = text.substr(b, e - b);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
    at.fail(what, "a finite number is needed", text);
  return v;
}

std::vector<double> numbers(const Where& at, std::string_view what, std::string_view text) {
  std::vector<double> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && space(text[i])) ++i;
    std::size_t j = i;
    while (j < text.size() && !space(text[j])) ++j;
    if (j > i) out.push_back(number(at, what, text.substr(i, j - i)));
    i = j;
  }
  return out;
}

std::vector<double> numbers(const Where& at, std::string_view what, std::string_view text,
                            std::size_t n) {
  // Each token checked first, so a "nan" is named as such, then the count.
  std::vector<double> out = numbers(at, what, text);
  if (out.size() != n) at.fail(what, fmt::format("{} numbers are needed", n), text);
  return out;
}

double number_or(const Where& at, const pugi::xml_node& node, const char* name, double fallback) {
  const pugi::xml_attribute a = node.attribute(name);
  return a ? number(at, name, a.value()) : fallback;
}

std::vector<pugi::xml_node> flame_nodes(const pugi::xml_node& root) {
  std::vector<pugi::xml_node> out;
  for (pugi::xml_node n = root.first_child(); n; n = n.next_sibling()) {
    if (n.type() != pugi::node_element) continue;
    if (std::string_view(n.name()) == "flame") {
      out.push_back(n);
    } else {
      const std::vector<pugi::xml_node> inner = flame_nodes(n);
      out.insert(out.end(), inner.begin(), inner.end());
    }
  }
  return out;
}

}  // namespace ifsfx::flame::detail
