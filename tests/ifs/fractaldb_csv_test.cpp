// SPDX-License-Identifier: Apache-2.0
// FractalDB's category and weight files: what is read, and every bad input named by file and
// line with the same kind and message each time.
#include "ifs/fractaldb_csv.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::fractaldb {
namespace {

namespace fs = std::filesystem;

// The Error thrown by `f`, or a test failure.
template <class F>
Error error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error(ErrorKind::io, "");
}

// A category row in the reference search's own format (np.savetxt, "%.18e").
constexpr const char* kTwoMaps =
    "5.000000000000000000e-01,0.000000000000000000e+00,0.000000000000000000e+00,"
    "5.000000000000000000e-01,0.000000000000000000e+00,0.000000000000000000e+00,"
    "2.500000000000000000e-01\n"
    "5.000000000000000000e-01,0.000000000000000000e+00,0.000000000000000000e+00,"
    "5.000000000000000000e-01,5.000000000000000000e-01,2.500000000000000000e-01,"
    "7.500000000000000000e-01\n";

TEST(fractaldb_csv, reads_rows_in_ifsfx_map_order_with_p_as_written) {
  const Category c = parse_category(kTwoMaps, "cats/00042.csv");
  EXPECT_EQ(c.name, "00042");
  ASSERT_EQ(c.maps.size(), 2u);
  EXPECT_EQ(c.maps[1], (AffineMap{0.5, 0, 0, 0.5, 0.5, 0.25}));
  EXPECT_EQ(c.probabilities, (std::vector<double>{0.25, 0.75}));
  // Written back as the search writes it, the same bytes.
  EXPECT_EQ(category_text(c), kTwoMaps);
}

TEST(fractaldb_csv, takes_spaces_blank_lines_comments_crlf_and_a_plus_sign) {
  const Category c = parse_category(
      "# two halves\r\n\r\n 0.5 , 0, 0, 0.5, 0, 0, 0.5\r\n+0.5,0,0,0.5,0.5,0,0.5  # right\r\n",
      "x.csv");
  ASSERT_EQ(c.maps.size(), 2u);
  EXPECT_EQ(c.maps[1].e, 0.5);
}

TEST(fractaldb_csv, names_file_and_line_of_a_malformed_row) {
  const std::string text = "0.5,0,0,0.5,0,0,0.5\n\n0.5,0,0,0.5,0.5,0\n";
  const Error e = error_of([&] { parse_category(text, "cats/7.csv"); });
  EXPECT_EQ(e.kind(), ErrorKind::parse);
  EXPECT_STREQ(e.what(),
               "cats/7.csv:3: a category row a,b,c,d,e,f,p is 7 numbers separated by commas (got "
               "6)");
  EXPECT_STREQ(error_of([] { parse_category("0.5,0,0,0.5,x1,0,1\n", "c.csv"); }).what(),
               "c.csv:1: column 5 (e): expected a number (got 'x1')");
  EXPECT_STREQ(error_of([] { parse_category("0.5,0,0,0.5,0,0,1,\n", "c.csv"); }).what(),
               "c.csv:1: a category row a,b,c,d,e,f,p is 7 numbers separated by commas (got 8)");
  EXPECT_STREQ(error_of([] { parse_category("# nothing\n\n", "c.csv"); }).what(),
               "c.csv: no rows (a category row a,b,c,d,e,f,p is 7 numbers separated by commas)");
}

TEST(fractaldb_csv, refuses_non_finite_numbers_and_bad_probabilities) {
  Error e =
      error_of([] { parse_category("0.5,0,0,0.5,0,0,0.5\n0.5,nan,0,0.5,0,0,0.5\n", "c.csv"); });
  EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
  EXPECT_STREQ(e.what(), "c.csv:2: column 2 (b): must be a finite number (got nan)");
  e = error_of([] { parse_category("0.5,0,0,0.5,0,0,1.5\n0.5,0,0,0.5,0,0,-0.5\n", "c.csv"); });
  EXPECT_STREQ(e.what(), "c.csv:2: column 7 (p): a probability must be ≥ 0 (got -0.5)");
  e = error_of([] { parse_category("0.5,0,0,0.5,0,0,0.5\n0.5,0,0,0.5,1,0,0.25\n", "c.csv"); });
  EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
  EXPECT_STREQ(e.what(),
               "c.csv:2: the probabilities of column 7 (p) must sum to 1 over the 2 rows (got "
               "0.75)");
}

TEST(fractaldb_csv, refuses_maps_that_do_not_contract_on_average_as_the_search_drops_them) {
  // x ↦ 1.1 x grows on every step: the chaos game flies off and its points collapse.
  const Error e = error_of([] { parse_category("1.1,0,0,0.5,0,0,1\n", "cats/00003.csv"); });
  EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
  EXPECT_STREQ(e.what(),
               "cats/00003.csv: the maps do not contract on average (contraction rate 0.0953 per "
               "step, must be < 0): the chaos game flies off to infinity, and FractalDB's search "
               "drops such an IFS (its points collapse into a few pixels, below any filling "
               "rate)");
}

TEST(fractaldb_csv, accepts_maps_that_contract_only_in_the_long_run) {
  // A shear of norm 10 with both eigenvalues 0.9: its words of up to 3 maps grow (the mean log
  // contraction cannot prove it), its products shrink by 0.9 a step in the long run.
  const std::vector<AffineMap> shear{{0.9, 10, 0, 0.9, 0, 0}};
  Ifs ifs;
  ifs.maps = shear;
  EXPECT_GT(mean_log_contraction(ifs), 0);
  EXPECT_NEAR(contraction_rate(shear, {1.0}), std::log(0.9), 0.01);
  EXPECT_NO_THROW(parse_category("0.9,10,0,0.9,0,0,1\n", "shear.csv"));
}

TEST(fractaldb_csv, reads_weights_and_makes_the_reference_tables) {
  const auto w = parse_weights("0.8,1,1,1,1,1\n1,1,1,1,1,1.2\n", "w.csv");
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[1][5], 1.2);
  EXPECT_STREQ(error_of([] { parse_weights("1,1,1,1,1,1,1\n", "w.csv"); }).what(),
               "w.csv:1: a weight row wa,wb,wc,wd,we,wf is 6 numbers separated by commas (got 7)");
  // weights_0.1.csv: all ones third, each coefficient's four factors in turn, decimal values.
  const auto table = weights_table(0.1);
  ASSERT_EQ(table.size(), 25u);
  EXPECT_EQ(table[0], (Weight{0.8, 1, 1, 1, 1, 1}));
  EXPECT_EQ(table[2], (Weight{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(table[4], (Weight{1.2, 1, 1, 1, 1, 1}));
  EXPECT_EQ(table[5], (Weight{1, 0.8, 1, 1, 1, 1}));
  EXPECT_EQ(table[24], (Weight{1, 1, 1, 1, 1, 1.2}));
  EXPECT_EQ(weights_table(0.5)[0][0], 0.01);  // weights_0.5.csv's 1 − 2K
  EXPECT_EQ(weights_table(0.0125)[1][0], 0.9875);
  EXPECT_THROW(weights_table(0), Error);
}

TEST(fractaldb_csv, finds_category_files_below_a_folder_sorted_by_name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ifsfx-fractaldb-csv-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "csv1");
  fs::create_directories(dir / "csv0");
  std::ofstream(dir / "csv1" / "00001.csv") << kTwoMaps;
  std::ofstream(dir / "csv0" / "00002.csv") << kTwoMaps;
  std::ofstream(dir / "csv0" / "00000.csv") << kTwoMaps;
  std::ofstream(dir / "csv0" / "notes.txt") << "not a category";
  const auto files = category_files(dir);
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].filename(), "00000.csv");
  EXPECT_EQ(files[1], dir / "csv1" / "00001.csv");
  EXPECT_EQ(read_category(files[2]).name, "00002");
  std::ofstream(dir / "csv1" / "00000.csv") << kTwoMaps;
  EXPECT_EQ(error_of([&] { category_files(dir); }).kind(), ErrorKind::invalid_argument);
  EXPECT_EQ(error_of([&] { read_category(dir / "missing.csv"); }).kind(), ErrorKind::not_found);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ifsfx::fractaldb
