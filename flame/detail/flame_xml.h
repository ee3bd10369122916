// SPDX-License-Identifier: Apache-2.0
// What the flame reader's parts share: where in the file an attribute is (for one-line messages)
// and the checked conversion of attribute text to numbers.
#pragma once

#include <pugixml.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "flame/flame.h"
#include "flame/flame_file.h"

namespace ifsfx::flame::detail {

// The file and flame being read; `fail` throws Error{parse}:
//   "FILE: flame "NAME": WHAT: RULE (got TEXT)".
struct Where {
  std::string file;
  std::string flame;  // name, or "#INDEX" for an unnamed flame
  [[noreturn]] void fail(std::string_view what, std::string_view rule, std::string_view got) const;
  [[noreturn]] void fail(std::string_view what, std::string_view rule) const;
};

// The numbers of a whitespace-separated list; each must be a finite number.
std::vector<double> numbers(const Where& at, std::string_view what, std::string_view text);
// Exactly `n` finite numbers.
std::vector<double> numbers(const Where& at, std::string_view what, std::string_view text,
                            std::size_t n);
double number(const Where& at, std::string_view what, std::string_view text);

// The attribute `name` of `node` as a number, or `fallback` when absent.
double number_or(const Where& at, const pugi::xml_node& node, const char* name, double fallback);

// The xforms of <xform> / <finalxform> elements (flame_xform.cpp).
Xform parse_xform(const Where& at, const pugi::xml_node& node, const std::string& what,
                  bool is_final);

// The flame's palette: inline <palette>/<colors>/<color> elements, else palette="N" from the
// library (flame_palette.cpp). Throws when there is none or it has the wrong length.
Palette parse_palette(const Where& at, const pugi::xml_node& flame,
                      const FlameReadOptions& options);

// One <flame> element (flame_parse.cpp).
Flame parse_flame(const Where& at, const pugi::xml_node& node, const FlameReadOptions& options);

// The <flame> elements of a document, in order, not looking inside a flame.
std::vector<pugi::xml_node> flame_nodes(const pugi::xml_node& root);

}  // namespace ifsfx::flame::detail
