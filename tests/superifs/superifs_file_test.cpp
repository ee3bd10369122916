// SPDX-License-Identifier: Apache-2.0
// SuperIFS files: the shipped presets, and bad files rejected with file, line and rule.
#include "superifs/superifs_file.h"

#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "ifs/error.h"

namespace ifsfx {
namespace {

const char* const good = R"(name = "two"
probabilities = [1, 3]
[[ifs]]
maps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0]]
[[ifs]]
maps = [[0.4, 0, 0, 0.4, 0, 0], [0.4, 0, 0, 0.4, 0.6, 0]]
probabilities = [1, 2]
)";

TEST(superifs_file, parses_ifss_probabilities_and_colouring_defaults) {
  const auto p = parse_superifs_toml(good, "two.super.toml");
  EXPECT_EQ(p.super.name, "two");
  ASSERT_EQ(p.super.size(), 2u);
  EXPECT_EQ(p.super.maps(), 2u);
  EXPECT_EQ(p.super.ifs[1].maps[1], (AffineMap{0.4, 0, 0, 0.4, 0.6, 0}));
  EXPECT_EQ(p.super.ifs[1].probabilities, (std::vector<double>{1, 2}));
  const auto big_p = effective_probabilities(p.super);
  EXPECT_DOUBLE_EQ(big_p[0], 0.25);
  EXPECT_DOUBLE_EQ(big_p[1], 0.75);
  EXPECT_TRUE(p.super.colouring.empty());
  EXPECT_EQ(colouring_ifs(p.super, 1).size(), 2u);
  EXPECT_EQ(p.text, good);
}

TEST(superifs_file, ships_paper_fig4_as_in_the_paper) {
  const auto p = load_superifs("paper-fig4");
  EXPECT_EQ(p.origin, "shipped:paper-fig4.super.toml");
  ASSERT_EQ(p.super.size(), 2u);  // N = 2
  EXPECT_EQ(p.super.maps(), 3u);  // M = 3
  for (const auto& m : p.super.ifs[0].maps) EXPECT_NEAR(m.contraction(), 0.5, 1e-12);
  for (const auto& m : p.super.ifs[1].maps) EXPECT_NEAR(m.contraction(), 1.0 / 3, 1e-12);
  // Each F^n is a Sierpinski triangle: map m fixes corner m of one and the same triangle.
  for (std::size_t m = 0; m < 3; ++m) {
    const AffineMap& a = p.super.ifs[0].maps[m];
    const AffineMap& b = p.super.ifs[1].maps[m];
    const Point corner{a.e / (1 - a.a), a.f / (1 - a.d)};
    EXPECT_NEAR(b(corner).x, corner.x, 1e-12);
    EXPECT_NEAR(b(corner).y, corner.y, 1e-12);
  }
}

TEST(superifs_file, every_shipped_superifs_loads) {
  const auto list = list_shipped_superifs();
  ASSERT_GE(list.size(), 4u);  // paper-fig4 and at least three textures
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto p = load_superifs(list[i].name);
    EXPECT_EQ(p.super.size(), list[i].ifs);
    EXPECT_FALSE(list[i].description.empty()) << list[i].name;
    if (i > 0) {
      EXPECT_LT(list[i - 1].name, list[i].name);
    }
  }
}

// The studio saves edited superIFSs through to_toml: every number must come back exactly.
TEST(superifs_file, to_toml_reads_back_to_the_same_superifs) {
  auto presets = std::vector<SuperIfsPreset>{};
  for (const auto& s : list_shipped_superifs()) presets.push_back(load_superifs(s.name));
  auto odd = parse_superifs_toml(good, "two.super.toml");
  odd.super.view = Box{-0.1, 0.2, 1.0 / 3.0, 1.5};
  odd.super.colouring = {odd.super.ifs[1]};
  odd.super.ifs[0].name = "quote \" and \\ back";
  presets.push_back(odd);
  for (const auto& p : presets) {
    const SuperIfsPreset back = parse_superifs_toml(to_toml(p.super, "a \"description\""), "x");
    EXPECT_EQ(back.description, "a \"description\"");
    EXPECT_EQ(back.super.name, p.super.name);
    EXPECT_EQ(back.super.probabilities, p.super.probabilities) << p.super.name;
    EXPECT_EQ(back.super.view, p.super.view) << p.super.name;
    ASSERT_EQ(back.super.size(), p.super.size());
    for (std::size_t n = 0; n < p.super.size(); ++n) {
      EXPECT_EQ(back.super.ifs[n].name, p.super.ifs[n].name);
      EXPECT_EQ(back.super.ifs[n].maps, p.super.ifs[n].maps) << p.super.name << " IFS " << n + 1;
      EXPECT_EQ(back.super.ifs[n].probabilities, p.super.ifs[n].probabilities);
    }
    ASSERT_EQ(back.super.colouring.size(), p.super.colouring.size());
    for (std::size_t n = 0; n < p.super.colouring.size(); ++n)
      EXPECT_EQ(back.super.colouring[n].maps, p.super.colouring[n].maps);
  }
}

TEST(superifs_file, loads_a_path) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("superifs_file_test-" + std::to_string(getpid()) + ".super.toml");
  std::ofstream(path) << good;
  EXPECT_EQ(load_superifs(path.string()).super.size(), 2u);
  std::filesystem::remove(path);
}

void expect_error(const std::string& text, ErrorKind kind, const std::string& message) {
  try {
    parse_superifs_toml(text, "bad.super.toml");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_EQ(std::string(e.what()), message);
  }
}

void expect_prefix(const std::string& text, ErrorKind kind, const std::string& prefix) {
  try {
    parse_superifs_toml(text, "bad.super.toml");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix) << e.what();
  }
}

TEST(superifs_file, a_key_of_absurd_depth_is_refused_before_parsing) {
  std::string key = "ifs";
  for (int i = 0; i < 30000; ++i) key += ".maps";
  try {
    parse_superifs_toml("name = \"deep\"\n\n[[" + key + "]]\n", "deep.super.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_STREQ(e.what(),
                 "deep.super.toml:3: a dotted key of more than 32 parts (a preset needs a few)");
  }
}

TEST(superifs_file, rejects_syntax_errors_with_the_line) {
  expect_prefix("name = \"x\"\n[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]\n", ErrorKind::parse,
                "bad.super.toml:3");
}

TEST(superifs_file, rejects_bad_contents_with_the_line) {
  expect_error("name = \"x\"\n", ErrorKind::invalid_ifs,
               "bad.super.toml:1: a superIFS needs at least one [[ifs]] table (got 0)");
  expect_error(
      "[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0]]\n"
      "[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n",
      ErrorKind::invalid_ifs,
      "bad.super.toml:3: IFS 2: every IFS needs the same number of maps as IFS 1 "
      "(got 1 for 2)");
  expect_error("[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0],\n  [1.5, 0, 0, 0.5, 0.5, 0]]\n",
               ErrorKind::invalid_ifs,
               "bad.super.toml:1: IFS 1: map 2: contraction factor must be < 1 (got 1.5); "
               "allow_expansive accepts it if the IFS contracts on average");
  expect_error("[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0],\n  [0.5, 0, 0, 0.5, 0.5]]\n",
               ErrorKind::parse,
               "bad.super.toml:3: IFS 1 map 2: needs 6 numbers a b c d e f (got 5)");
  expect_error("[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, \"x\"]]\n", ErrorKind::parse,
               "bad.super.toml:2: IFS 1 map 1: must be a number (got a string)");
  expect_error("probabilities = [1, 2]\n[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n",
               ErrorKind::invalid_ifs,
               "bad.super.toml:1: probabilities: one per [[ifs]] is needed (got 2 for 1 IFSs)");
  expect_error("[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\nprobabilty = [1]\n", ErrorKind::parse,
               "bad.super.toml:3: IFS 1: unknown key 'probabilty' (known: name, maps, "
               "probabilities)");
  expect_error(
      "[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n[[colouring]]\n"
      "maps = [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0]]\n",
      ErrorKind::invalid_ifs,
      "bad.super.toml:3: colouring 1: needs as many maps as the IFSs (got 2 for 1)");
  expect_error("[[ifs]]\nmaps = [[0.5, 0, 0, 0, 0, 0]]\n", ErrorKind::invalid_ifs,
               "bad.super.toml: IFS 1 map 1: must be invertible, the V-variable raster inverts "
               "every map (got det 0)");
  expect_error("view = [0, 0, 1]\n[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n", ErrorKind::parse,
               "bad.super.toml:1: view: needs 4 numbers x0, y0, x1, y1 (got 3)");
}

TEST(superifs_file, reads_the_seamless_table) {
  const std::string ifs = "[[ifs]]\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n";
  EXPECT_FALSE(parse_superifs_toml(ifs, "x.super.toml").seamless);
  const SuperIfsPreset p =
      parse_superifs_toml("[seamless]\noffset = [0.5, 0.5]\n" + ifs, "x.super.toml");
  ASSERT_TRUE(p.seamless);
  EXPECT_EQ(p.seamless->offset, (Point{0.5, 0.5}));
  expect_error("[seamless]\nview = [0, 0, 0, 1]\n" + ifs, ErrorKind::parse,
               "bad.super.toml:2: seamless: view: needs finite x0 < x1 and y0 < y1 (got 0, 0, 0, "
               "1)");
  // The shipped ones offered as seamless tiles say so in the list.
  int offered = 0;
  for (const SuperIfsSummary& s : list_shipped_superifs())
    offered += s.seamless == load_superifs(s.name).seamless.has_value() && s.seamless;
  EXPECT_GE(offered, 3);
}

TEST(superifs_file, unknown_name_lists_the_shipped_presets) {
  try {
    load_superifs("no-such-superifs");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("no-such-superifs: no such superIFS preset or file (shipped: ", 0), 0u);
    EXPECT_NE(what.find("paper-fig4"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace ifsfx
