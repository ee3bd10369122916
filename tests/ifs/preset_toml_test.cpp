// SPDX-License-Identifier: Apache-2.0
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx {
namespace {

// parse_ifs_toml(text) must throw Error{kind} with exactly this message.
void expect_error(const std::string& text, ErrorKind kind, const std::string& message) {
  try {
    parse_ifs_toml(text, "fern.toml");
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_EQ(std::string(e.what()), message);
  }
}

void expect_same_ifs(const Ifs& a, const Ifs& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.maps, b.maps);
  EXPECT_EQ(a.probabilities, b.probabilities);
  EXPECT_EQ(a.colours, b.colours);
}

TEST(parse_ifs_toml, reads_name_description_maps_probabilities_and_colours) {
  const IfsPreset p = parse_ifs_toml(R"(name = "two"
description = "two maps"
maps = [[0.5, 0, 0, 0.5, 0, 0],   # integers are numbers too
        [0.25, -0.5, 0.5, 0.25, 1, 2.5e-1]]
probabilities = [1, 3]
colours = ["#ff8000", [0.25, 0.5, 1]]
)",
                                     "two.toml");
  EXPECT_EQ(p.ifs.name, "two");
  EXPECT_EQ(p.description, "two maps");
  EXPECT_EQ(p.origin, "two.toml");
  ASSERT_EQ(p.ifs.size(), 2u);
  EXPECT_EQ(p.ifs.maps[0], (AffineMap{0.5, 0, 0, 0.5, 0, 0}));
  EXPECT_EQ(p.ifs.maps[1], (AffineMap{0.25, -0.5, 0.5, 0.25, 1, 0.25}));
  EXPECT_EQ(p.ifs.probabilities, (std::vector<double>{1, 3}));
  ASSERT_EQ(p.ifs.colours.size(), 2u);
  EXPECT_EQ(p.ifs.colours[0], (Rgb{1.0, 128 / 255.0, 0.0}));
  EXPECT_EQ(p.ifs.colours[1], (Rgb{0.25, 0.5, 1.0}));
  EXPECT_EQ(p.text.substr(0, 12), "name = \"two\"");
}

TEST(parse_ifs_toml, optional_fields_default_and_the_name_is_the_file_stem) {
  const IfsPreset p = parse_ifs_toml("maps = [[0.5, 0, 0, 0.5, 0, 0]]\n", "presets/half.toml");
  EXPECT_EQ(p.ifs.name, "half");
  EXPECT_EQ(p.description, "");
  EXPECT_TRUE(p.ifs.probabilities.empty());
  EXPECT_TRUE(p.ifs.colours.empty());
}

TEST(parse_ifs_toml, a_map_with_five_numbers_is_reported_with_its_line) {
  expect_error(R"(name = "fern"
# x' = a x + b y + e, y' = c x + d y + f
maps = [
  [0.00, 0.00, 0.00, 0.16, 0.00, 0.00],

  # the second map lost a number
  [0.85, 0.04, -0.04, 0.85, 0.00],
]
)",
               ErrorKind::parse, "fern.toml:7: map 2: needs 6 numbers a b c d e f (got 5)");
}

TEST(parse_ifs_toml, a_misspelt_key_is_reported_with_its_line) {
  expect_error(
      R"(name = "fern"
maps = [[0.5, 0, 0, 0.5, 0, 0]]
probabilites = [1]
)",
      ErrorKind::parse,
      "fern.toml:3: unknown key 'probabilites' "
      "(known: name, description, maps, probabilities, colours, allow_expansive, seamless)");
}

TEST(parse_ifs_toml, a_toml_syntax_error_is_reported_with_its_line) {
  try {
    parse_ifs_toml("name = \"fern\"\n\nmaps = [[0.5, 0, 0, 0.5, 0, 0]\n", "fern.toml");
    ADD_FAILURE() << "an unclosed array was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    // toml++ words the rule; the line (of the unclosed array) is ours to check.
    EXPECT_EQ(std::string(e.what()).rfind("fern.toml:3: ", 0), 0u) << e.what();
  }
  try {
    parse_ifs_toml("name = \"fern\"\nmaps == 3\n", "fern.toml");
    ADD_FAILURE() << "'==' was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_EQ(std::string(e.what()).rfind("fern.toml:2: ", 0), 0u) << e.what();
  }
}

// "a.a.a...": a dotted key of `parts` parts.
std::string dotted(int parts, const std::string& part = "a") {
  std::string key = part;
  for (int i = 1; i < parts; ++i) key.append(".").append(part);
  return key;
}

// A key of tens of thousands of parts overflowed the stack inside toml++ (a segfault): the text's
// shape is checked before toml++ sees it, with one message naming the file and line.
TEST(parse_ifs_toml, keys_of_absurd_depth_are_refused_before_parsing) {
  const std::string parts_message =
      "fern.toml:2: a dotted key of more than 32 parts (a preset "
      "needs a few)";
  expect_error("name = \"x\"\n" + dotted(50000) + " = 1\n", ErrorKind::parse, parts_message);
  expect_error("name = \"x\"\n[" + dotted(50000) + "]\n", ErrorKind::parse, parts_message);
  expect_error("name = \"x\"\n[[" + dotted(40000, "\"q\"") + "]]\n", ErrorKind::parse,
               parts_message);
  expect_error("name = \"x\"\n" + dotted(33) + " = 1\n", ErrorKind::parse, parts_message);
  expect_error("name = \"x\"\nmaps = " + std::string(100000, '[') + std::string(100000, ']'),
               ErrorKind::parse,
               "fern.toml:2: arrays and tables nested more than 32 deep (a preset needs a few)");
  expect_error("x = " + std::string(33, '{') + "a = 1" + std::string(33, '}'), ErrorKind::parse,
               "fern.toml:1: arrays and tables nested more than 32 deep (a preset needs a few)");
  expect_error(std::string(17u << 20, ' '), ErrorKind::parse,
               "fern.toml: larger than any preset (got 17825792 bytes; at most 16 MiB)");
}

// The deepest text the check lets through is parsed by toml++ without harm (the sanitizer build
// runs this with its larger stack frames), and dots in strings and comments are not key parts.
TEST(parse_ifs_toml, the_deepest_text_allowed_parses_safely) {
  std::string deep = "x = ";
  for (int i = 0; i < 31; ++i) deep.append("{").append(dotted(32)).append(" = ");
  deep.append("1").append(31, '}').append("\n");
  expect_error(deep, ErrorKind::parse,
               "fern.toml:1: unknown key 'x' (known: name, description, maps, probabilities, "
               "colours, allow_expansive, seamless)");
  const std::string dots = dotted(5000, "b");
  expect_error("description = \"" + dots + "\"  # " + dots + "\nname = '" + dots +
                   "'\nnotes = \"\"\"\n" + dots + "\n\"\"\"\n",
               ErrorKind::parse,
               "fern.toml:3: unknown key 'notes' (known: name, description, maps, probabilities, "
               "colours, allow_expansive, seamless)");
}

TEST(parse_ifs_toml, values_of_the_wrong_type_are_reported_with_their_line) {
  expect_error("maps = [[0.5, 0, 0, \"half\", 0, 0]]\n", ErrorKind::parse,
               "fern.toml:1: map 1: must be a number (got a string)");
  expect_error("name = 3\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n", ErrorKind::parse,
               "fern.toml:1: name: must be a string (got an integer)");
  expect_error("maps = [0.5, 0, 0, 0.5, 0, 0]\n", ErrorKind::parse,
               "fern.toml:1: map 1: must be an array (got a number)");
  expect_error("name = \"x\"\n", ErrorKind::parse,
               "fern.toml: maps: an IFS needs a 'maps' array of [a, b, c, d, e, f] (got none)");
  expect_error("maps = []\n", ErrorKind::invalid_ifs,
               "fern.toml:1: maps: an IFS needs at least one map (got 0)");
}

TEST(parse_ifs_toml, nan_and_inf_coefficients_are_invalid_with_their_line) {
  expect_error("maps = [\n  [0.5, 0, 0, 0.5, 0, 0],\n  [0.5, 0, 0, 0.5, nan, 0],\n]\n",
               ErrorKind::invalid_ifs,
               "fern.toml:3: map 2: coefficients must be finite numbers (got nan)");
  expect_error("maps = [[0.5, -inf, 0, 0.5, 0, 0]]\n", ErrorKind::invalid_ifs,
               "fern.toml:1: map 1: coefficients must be finite numbers (got -inf)");
}

TEST(parse_ifs_toml, negative_all_zero_and_miscounted_probabilities_are_invalid) {
  const std::string maps = "maps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 1, 0]]\n";
  expect_error(maps + "probabilities = [0.5,\n  -0.5]\n", ErrorKind::invalid_ifs,
               "fern.toml:3: map 2: probability must be a finite number ≥ 0 (got -0.5)");
  expect_error(maps + "probabilities = [0, 0.0]\n", ErrorKind::invalid_ifs,
               "fern.toml:2: probabilities: they must not all be zero (got sum 0)");
  expect_error(maps + "probabilities = [1]\n", ErrorKind::invalid_ifs,
               "fern.toml:2: probabilities: one per map is needed (got 1 for 2 maps)");
  expect_error(maps + "probabilities = [1, inf]\n", ErrorKind::invalid_ifs,
               "fern.toml:2: map 2: probability must be a finite number ≥ 0 (got inf)");
}

TEST(parse_ifs_toml, bad_colours_are_reported_with_their_line) {
  const std::string maps = "maps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 1, 0]]\n";
  expect_error(maps + "colours = [\"#ff0000\", \"red\"]\n", ErrorKind::parse,
               "fern.toml:2: map 2: colour: must be \"#rrggbb\" or [r, g, b] in [0, 1] "
               "(got \"red\")");
  expect_error(maps + "colours = [\"#ff0000\", [1, 0]]\n", ErrorKind::parse,
               "fern.toml:2: map 2: colour: must be \"#rrggbb\" or [r, g, b] in [0, 1] "
               "(got 2 numbers)");
  expect_error(maps + "colours = [[1, 0, 255], \"#00ff00\"]\n", ErrorKind::parse,
               "fern.toml:2: map 1: colour: components must lie in [0, 1] (got 255)");
  expect_error(maps + "colours = [\"#ff0000\"]\n", ErrorKind::invalid_ifs,
               "fern.toml:2: colours: one per map is needed (got 1 for 2 maps)");
}

// A preset offered as a seamless tile says so in a [seamless] table, with an optional tile and
// offset (docs/seamless.md); a preset without one is not offered.
TEST(parse_ifs_toml, reads_the_seamless_table) {
  const std::string maps = "maps = [[0.5, 0, 0, 0.5, 0, 0]]\n";
  EXPECT_FALSE(parse_ifs_toml(maps, "fern.toml").seamless);
  const IfsPreset plain = parse_ifs_toml(maps + "[seamless]\n", "fern.toml");
  ASSERT_TRUE(plain.seamless);
  EXPECT_FALSE(plain.seamless->view);
  EXPECT_EQ(plain.seamless->offset, (Point{0, 0}));
  const IfsPreset full =
      parse_ifs_toml(maps + "[seamless]\nview = [0, -1, 2, 1.5]\noffset = [0.5, 0.25]\n", "f.toml");
  ASSERT_TRUE(full.seamless && full.seamless->view);
  EXPECT_EQ(*full.seamless->view, (Box{0, -1, 2, 1.5}));
  EXPECT_EQ(full.seamless->offset, (Point{0.5, 0.25}));
}

TEST(parse_ifs_toml, a_bad_seamless_table_is_reported_with_its_line) {
  const std::string maps = "maps = [[0.5, 0, 0, 0.5, 0, 0]]\n";
  expect_error(maps + "seamless = true\n", ErrorKind::parse,
               "fern.toml:2: seamless: must be a table with view and offset (got a boolean)");
  expect_error(maps + "[seamless]\nofset = [0.5, 0.5]\n", ErrorKind::parse,
               "fern.toml:3: seamless: unknown key 'ofset' (known: view, offset)");
  expect_error(maps + "[seamless]\nview = [0, 0, 1]\n", ErrorKind::parse,
               "fern.toml:3: seamless: view: needs 4 numbers x0, y0, x1, y1 (got 3)");
  expect_error(maps + "[seamless]\nview = [1, 0, 0, 1]\n", ErrorKind::parse,
               "fern.toml:3: seamless: view: needs finite x0 < x1 and y0 < y1 (got 1, 0, 0, 1)");
  expect_error(maps + "[seamless]\noffset = [1, 0]\n", ErrorKind::parse,
               "fern.toml:3: seamless: offset: needs 2 fractions of the tile in [0, 1) (got 1, 0)");
  expect_error(maps + "[seamless]\noffset = [0.5]\n", ErrorKind::parse,
               "fern.toml:3: seamless: offset: needs 2 fractions of the tile in [0, 1) (got 0.5)");
}

TEST(to_toml, round_trips_exactly) {
  Ifs ifs;
  ifs.name = "odd \"name\" \\ with\ttabs";
  ifs.maps = {{1.0 / 3, -2.0 / 7, std::sqrt(2.0) / 3, 0.1, 1e-300, -123456789.125},
              {0.0, -0.0, 5e-324, 0.5, 1e20, 3}};
  ifs.probabilities = {0.1, 0.7000000000000001};
  ifs.colours = {{1.0, 128 / 255.0, 0.0}, {0.1, 1.0 / 3, 0.5}};
  const std::string description = "line one\nline \"two\"";
  const std::string text = to_toml(ifs, description);
  const IfsPreset back = parse_ifs_toml(text, "round.toml");
  expect_same_ifs(back.ifs, ifs);
  EXPECT_EQ(back.description, description);
  // Colours that are exactly k/255 are written as "#rrggbb", the others as numbers.
  EXPECT_NE(text.find("\"#ff8000\""), std::string::npos) << text;
  EXPECT_NE(text.find("[0.1, 0.3333333333333333, 0.5]"), std::string::npos) << text;
}

TEST(to_toml, writes_the_shortest_numbers_that_read_back) {
  Ifs ifs;
  ifs.name = "fern";
  ifs.maps = {{0.85, 0.04, -0.04, 0.85, 0, 1.6}};
  const std::string text = to_toml(ifs);
  EXPECT_NE(text.find("[0.85, 0.04, -0.04, 0.85, 0.0, 1.6]"), std::string::npos) << text;
  EXPECT_EQ(text.find("probabilities"), std::string::npos);
  EXPECT_EQ(text.find("description"), std::string::npos);
  expect_same_ifs(parse_ifs_toml(text, "fern.toml").ifs, ifs);
}

}  // namespace
}  // namespace ifsfx
