// SPDX-License-Identifier: Apache-2.0
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx {
namespace {

// parse_fractint(text) must throw Error{kind} with exactly this message.
void expect_error(const std::string& text, ErrorKind kind, const std::string& message) {
  try {
    parse_fractint(text, "test.ifs");
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_EQ(std::string(e.what()), message);
  }
}

constexpr const char* fern_text = R"(; Barnsley's fern as Fractint writes it
fern { ; comment after the brace
 0   0    0  .16 0 0   .01
.85 .04 -.04 .85 0 1.6 .85
.2 -.26  .23 .22 0 1.6 .07
-.15 .28 .26 .24 0 .44 .07
}
)";

TEST(parse_fractint, fern_equals_the_native_fern_preset) {
  const auto entries = parse_fractint(fern_text, "fern.ifs");
  ASSERT_EQ(entries.size(), 1u);
  const IfsPreset native = load_ifs("barnsley-fern");
  EXPECT_EQ(entries[0].ifs.name, "fern");
  EXPECT_EQ(entries[0].ifs.maps, native.ifs.maps);
  EXPECT_EQ(entries[0].ifs.probabilities, native.ifs.probabilities);
  EXPECT_EQ(entries[0].description, "comment after the brace");
  EXPECT_EQ(entries[0].origin, "fern.ifs:fern");
  EXPECT_EQ(entries[0].text.substr(0, 6), "fern {");
}

TEST(parse_fractint, reads_every_entry_with_comments_commas_and_tabs) {
  const auto entries = parse_fractint(
      "; a file of two entries\n"
      "half{.5,0,0,.5,0,0,.5 ; two maps, commas\n"
      "     .5,0,0,.5,1,0,.5}\n"
      "\n"
      "third\t{\t; tabs\n"
      "\t+.25\t0\t0\t0.25\t1e-1\t-2E-1\t1 ; a third map, scientific notation\n"
      "}\n",
      "test.ifs");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].ifs.name, "half");
  EXPECT_EQ(entries[0].ifs.maps,
            (std::vector<AffineMap>{{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 1, 0}}));
  EXPECT_EQ(entries[0].ifs.probabilities, (std::vector<double>{0.5, 0.5}));
  EXPECT_EQ(entries[1].ifs.name, "third");
  EXPECT_EQ(entries[1].ifs.maps, (std::vector<AffineMap>{{0.25, 0, 0, 0.25, 0.1, -0.2}}));
  EXPECT_EQ(entries[1].ifs.probabilities, (std::vector<double>{1}));
  EXPECT_EQ(entries[1].description, "tabs");
}

TEST(parse_fractint, an_entry_without_p_gets_default_probabilities) {
  const auto entries = parse_fractint(
      "nop {\n 0.5 0 0 0.5 0 0\n 0.5 0 0 0.5 1 0\n 0.5 0 0 0.5 0 1\n}\n", "test.ifs");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].ifs.size(), 3u);
  EXPECT_EQ(entries[0].ifs.maps[2], (AffineMap{0.5, 0, 0, 0.5, 0, 1}));
  EXPECT_TRUE(entries[0].ifs.probabilities.empty());
}

// One map x/2 + (i, 0), with a probability of 1/6 or none.
std::string map_line(int i, bool with_p) {
  return "0.5 0 0 0.5 " + std::to_string(i) + " 0" + (with_p ? " 0.16666666666666667\n" : "\n");
}

TEST(parse_fractint, a_count_fitting_both_six_and_seven_reads_p_when_they_are_probabilities) {
  // 42 numbers: six maps with p, or seven without. Read with p when the p sum to 1.
  std::string with_p = "e {\n";
  for (int i = 0; i < 6; ++i) with_p += map_line(i, true);
  EXPECT_EQ(parse_fractint(with_p + "}\n", "test.ifs")[0].ifs.size(), 6u);
  std::string without_p = "e {\n";
  for (int i = 0; i < 7; ++i) without_p += map_line(i, false);
  const auto entry = parse_fractint(without_p + "}\n", "test.ifs")[0];
  EXPECT_EQ(entry.ifs.size(), 7u);
  EXPECT_TRUE(entry.ifs.probabilities.empty());
}

TEST(parse_fractint, a_count_of_thirteen_numbers_is_rejected) {
  expect_error(
      "; one 3-D map without its tag\n"
      "odd {\n .5 0 0 .5 0 0 .5\n .5 0 0 .5 1 0\n}\n",
      ErrorKind::parse,
      "test.ifs:2: entry 'odd': needs 7 numbers per map (a b c d e f p) or 6 (a b c d e f) "
      "(got 13, a multiple of neither)");
}

TEST(parse_fractint, a_3d_entry_is_rejected_naming_it_and_its_line) {
  expect_error(
      "fern { 0 0 0 .16 0 0 1 }\n"
      "\n"
      "3dfern (3D) {\n"
      "   .00  .00 0 .0 .18 .0 0  0.0 0.00 0 0.0 0 .01\n"
      "   .85  .00 0 .0 .85 .1 0 -0.1 0.85 0 1.6 0 .99\n"
      "}\n",
      ErrorKind::unsupported,
      "test.ifs:3: entry '3dfern': only 2-D IFSs are supported (got a (3D) entry)");
}

TEST(parse_fractint, a_missing_brace_is_reported_with_its_line) {
  expect_error("first {\n .5 0 0 .5 0 0 1\n\nsecond {\n .5 0 0 .5 0 0 1\n}\n", ErrorKind::parse,
               "test.ifs:4: entry 'first': missing '}' before the next entry 'second'");
  expect_error("first {\n .5 0 0 .5 0 0 1\n{\n", ErrorKind::parse,
               "test.ifs:3: entry 'first': missing '}' before the next '{'");
  expect_error("last {\n .5 0 0 .5 0 0 1\n", ErrorKind::parse,
               "test.ifs:1: entry 'last': missing '}' (got the end of the file)");
  expect_error("open\n .5 0 0 .5 0 0 1\n}\n", ErrorKind::parse,
               "test.ifs:2: entry 'open': expected '{' after the name (got '.5')");
  expect_error("{ .5 0 0 .5 0 0 1 }\n", ErrorKind::parse,
               "test.ifs:1: an entry starts with its name, as in NAME { a b c d e f p ... } "
               "(got '{')");
}

// Fractint reads no number on the line of the opening brace, so artists write notes there
// without a ';' (Tony Hanmer's sqs02.ifs: "sq475a {Tony Hanmer 23/1/2004, Designed with
// BRAZIL"): such a line is the description. A brace line that starts with a number is numbers.
TEST(parse_fractint, a_note_after_the_brace_without_a_semicolon_is_the_description) {
  const auto entries = parse_fractint(
      "sq {Tony Hanmer 23/1/2004, Designed with BRAZIL ; and a comment\n"
      ".5 0 0 .5 0 0 .5\n"
      ".5 0 0 .5 1 0 .5\n"
      "}\n"
      "one {.5 0 0 .5 0 0 .5\n"
      ".5 0 0 .5 1 0 .5}\n",
      "test.ifs");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].description, "Tony Hanmer 23/1/2004, Designed with BRAZIL");
  EXPECT_EQ(entries[0].ifs.maps,
            (std::vector<AffineMap>{{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 1, 0}}));
  EXPECT_EQ(entries[1].ifs.maps, entries[0].ifs.maps);
  // A typo on a brace line that starts with numbers is still a typo, not a note.
  expect_error("e { .5 0 0 .5 0 0 1O\n .5 0 0 .5 1 0 .5\n}\n", ErrorKind::parse,
               "test.ifs:1: entry 'e': not a number (got '1O')");
  // A note on the line of a one-line entry is not taken either: Fractint would not read it.
  expect_error("w { Tony .5 0 0 .5 0 0 1 }\n", ErrorKind::parse,
               "test.ifs:1: entry 'w': not a number (got 'Tony')");
}

TEST(parse_fractint, a_token_that_is_not_a_number_is_reported_with_its_line) {
  expect_error("bad {\n .5 0 0 .5 0 0 1\n .5 0 0 .5 1O 0 1\n}\n", ErrorKind::parse,
               "test.ifs:3: entry 'bad': not a number (got '1O')");
}

TEST(parse_fractint, bad_values_are_invalid_with_their_line) {
  expect_error("e {\n .5 0 0 .5 0 0 1\n .5 0 0 .5 nan 0 1\n}\n", ErrorKind::invalid_ifs,
               "test.ifs:3: entry 'e': map 2: coefficients must be finite numbers (got nan)");
  expect_error("e {\n .5 0 0 .5 0 0 1\n .5 0 0 .5 1 0\n inf\n}\n", ErrorKind::invalid_ifs,
               "test.ifs:4: entry 'e': map 2: probability must be a finite number (got inf)");
  expect_error("e {\n .5 0 0 .5 0 0 0\n .5 0 0 .5 1 0 0\n}\n", ErrorKind::invalid_ifs,
               "test.ifs:1: entry 'e': probabilities: they must not all be zero (got sum 0)");
  expect_error("empty { ; nothing here\n}\n", ErrorKind::invalid_ifs,
               "test.ifs:1: entry 'empty': an IFS needs at least one map (got 0 numbers)");
}

// Fractint's selection rule, by hand: the cumulative sums S_k of the weights, their running
// maximum clamped to [0, 1] L_k, map k < N−1 gets L_k − L_{k−1}, the last map 1 − L_{N−2}.
TEST(fractint_probabilities, follow_a_hand_computed_table) {
  struct Row {
    std::vector<double> weights, expected;
  };
  const Row table[] = {
      // probabilities already: kept as they are
      {{0.01, 0.85, 0.07, 0.07}, {0.01, 0.85, 0.07, 0.07}},
      // a negative first weight: S = −1/7, 5/14, 6/7; map 1 gets nothing, map 2 loses 1/7
      {{-0.1428571, 0.5, 0.5}, {0, 0.3571429, 0.6428571}},
      // a negative weight inside: S = .3, .2, .5, 1; L = .3, .3, .5
      {{0.3, -0.1, 0.3, 0.5}, {0.3, 0, 0.2, 0.5}},
      // a large negative weight: S = .5, −.2, .2, .5; L = .5, .5, .5
      {{0.5, -0.7, 0.4, 0.3}, {0.5, 0, 0, 0.5}},
      // a sum above 1 is cut: S = .5, .9, 1.2
      {{0.5, 0.4, 0.3}, {0.5, 0.4, 0.1}},
      {{1.5, 0.5}, {1, 0}},
      // a sum below 1 leaves the rest to the last map
      {{0.2, 0.2, 0.2}, {0.2, 0.2, 0.6}},
      {{0.333333, 0.333333, 0.333333}, {0.333333, 0.333333, 0.333334}},
      // nothing reached: the last map takes everything
      {{-0.5, -0.5}, {0, 1}},
  };
  for (const Row& row : table) {
    const std::vector<double> p = fractint_probabilities(row.weights);
    ASSERT_EQ(p.size(), row.expected.size());
    for (std::size_t k = 0; k < p.size(); ++k)
      EXPECT_NEAR(p[k], row.expected[k], 1e-12)
          << "weights " << ::testing::PrintToString(row.weights) << ", map " << k;
  }
}

// The same rule as Fractint codes it (lorenz.c's ifs loop: walk the cumulative sum while it is
// below r, stop at the last map), applied to a fine grid of r: the share of each map is its
// effective probability, for weight vectors with negative entries and sums off 1.
TEST(fractint_probabilities, match_the_literal_walk_over_r) {
  const auto walk = [](const std::vector<double>& w, double r) {
    std::size_t k = 0;
    double sum = w[0];
    while (sum < r && k + 1 < w.size()) sum += w[++k];
    return k;
  };
  const std::vector<std::vector<double>> cases = {{-0.1428571, 0.5, 0.5},
                                                  {0.2, -0.3, 0.6, 0.1, 0.9},
                                                  {0.1, 0.1, -0.05, 0.2, 0.1},
                                                  {0.7, 0.6, -0.9, 0.5, 0.2}};
  constexpr int kSteps = 1'000'000;
  for (const auto& w : cases) {
    std::vector<double> share(w.size(), 0.0);
    for (int i = 0; i < kSteps; ++i) share[walk(w, (i + 0.5) / kSteps)] += 1.0 / kSteps;
    const std::vector<double> p = fractint_probabilities(w);
    for (std::size_t k = 0; k < w.size(); ++k)
      EXPECT_NEAR(p[k], share[k], 2e-6) << ::testing::PrintToString(w) << ", map " << k;
  }
}

// An entry with a negative weight (as Fractint designers' files have) reads, with the effective
// probabilities of the rule: its first map is never drawn.
TEST(parse_fractint, a_negative_weight_gives_fractints_probabilities) {
  const auto entries = parse_fractint(R"(shortened { ; a negative weight first
 .25  0    0   .25  0    0   -0.1428571
 .5   .5  -.5  .5   0    0    0.5
 .5   .5  -.5  .5   .5  -.5   0.5
}
)",
                                      "neg.ifs");
  ASSERT_EQ(entries.size(), 1u);
  const std::vector<double>& p = entries[0].ifs.probabilities;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], 0);
  EXPECT_NEAR(p[1], 0.3571429, 1e-12);
  EXPECT_NEAR(p[2], 0.6428571, 1e-12);
  EXPECT_EQ(entries[0].format, PresetFormat::fractint);
}

TEST(parse_fractint, an_empty_file_has_no_entries) {
  EXPECT_TRUE(parse_fractint("; only a comment\n\n", "test.ifs").empty());
}

}  // namespace
}  // namespace ifsfx
