// SPDX-License-Identifier: Apache-2.0
// Reading a preset's TOML tree with one-line errors "FILE:LINE: what": the checks the IFS reader
// (ifs/preset_toml.cpp) and the superIFS reader (superifs/superifs_file.cpp) share, so that both
// formats report a misspelt key, a value of the wrong type or a short map row alike.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "ifs/affine_map.h"
#include "ifs/error.h"
#include "ifs/tiles.h"

namespace ifsfx::detail {

class TomlReader {
 public:
  explicit TomlReader(std::string filename) : filename_(std::move(filename)) {}

  // "FILE:LINE" of a place in the file.
  std::string at(const toml::source_region& where) const;
  [[noreturn]] void fail(ErrorKind kind, const toml::source_region& where,
                         const std::string& what) const;

  // The whole file; a syntax error is Error{parse} at its line. The text's shape is checked
  // first (check_shape): toml++ must never see what would exhaust the stack.
  toml::table parse(std::string_view text) const;

  // Error{parse} "FILE:LINE: ..." for a text no preset has and toml++ cannot take safely: a
  // dotted key of more than 32 parts, arrays and tables nested more than 32 deep, more than 16 MiB.
  void check_shape(std::string_view text) const;

  // Keys other than `allowed` are typos that would silently change the result: Error{parse}
  // "CONTEXTunknown key 'K' (known: A, B, ...)".
  void check_keys(const toml::table& table, std::initializer_list<std::string_view> allowed,
                  const std::string& context = {}) const;

  // Values of one type, else Error{parse} "WHAT: must be a string (got an integer)" and the like.
  std::string string(const toml::node& node, const std::string& what) const;
  bool boolean(const toml::node& node, const std::string& what) const;
  double number(const toml::node& node, const std::string& what) const;  // integer or float
  const toml::array& array(const toml::node& node, const std::string& what) const;
  std::vector<double> numbers(const toml::node& node, const std::string& what) const;

  // The maps of an IFS: a non-empty array of rows [a, b, c, d, e, f] of finite numbers. Messages
  // name "PREFIX map N" / "PREFIX maps" (the prefix empty for a one-IFS file).
  std::vector<AffineMap> maps(const toml::node& node, const std::string& prefix = {}) const;

  // A [seamless] table (ifs/tiles.h): `view` (4 finite numbers, x0 < x1, y0 < y1) and `offset`
  // (2 numbers in [0, 1)), both optional; Error{parse} "seamless: ..." otherwise.
  SeamlessTile seamless(const toml::node& node) const;

  // "a string", "an integer", ... for messages.
  static std::string_view type_name(const toml::node& node);

 private:
  std::string filename_;
};

}  // namespace ifsfx::detail
