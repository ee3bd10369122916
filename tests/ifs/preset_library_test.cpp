// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx {
namespace {

namespace fs = std::filesystem;

// load_ifs(spec) must throw Error{kind} with exactly this message.
void expect_error(const std::string& spec, ErrorKind kind, const std::string& message,
                  const ValidateOptions& options = {}) {
  try {
    load_ifs(spec, options);
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_EQ(std::string(e.what()), message);
  }
}

// A scratch folder of its own for each test, removed at the end.
class TempDir {
 public:
  TempDir() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / fmt_name(test->test_suite_name(), test->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path file = path_ / name;
    std::ofstream(file) << text;
    return file.string();
  }

 private:
  static std::string fmt_name(const std::string& suite, const std::string& test) {
    return "ifsfx-" + suite + "-" + test;
  }
  fs::path path_;
};

bool needs_allow_expansive(const std::string& name) {
  return name == "square-tiling-2" || name == "square-tiling-3";
}

TEST(shipped_presets, include_every_preset_of_the_issue) {
  std::vector<std::string> names;
  for (const auto& p : list_shipped_presets()) names.push_back(p.name);
  for (const char* wanted : {"sierpinski-triangle",
                             "right-sierpinski",
                             "barnsley-fern",
                             "maple-leaf",
                             "heighway-dragon",
                             "twin-dragon",
                             "levy-c-curve",
                             "koch-curve",
                             "square-tiling-2",
                             "square-tiling-3",
                             "square-tiling-4",
                             "square-tiling-9",
                             "binary",
                             "coral",
                             "crystal",
                             "dragon",
                             "fern",
                             "floor",
                             "koch3",
                             "spiral",
                             "swirl5",
                             "tree",
                             "triangle",
                             "zigzag2"})
    EXPECT_NE(std::find(names.begin(), names.end(), wanted), names.end()) << wanted;
  // Names are unique, or a name would load another preset than the one listed.
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

TEST(shipped_presets, every_one_loads_validates_and_describes_itself) {
  for (const auto& summary : list_shipped_presets()) {
    SCOPED_TRACE(summary.name);
    const IfsPreset p =
        load_ifs(summary.name, {.allow_expansive = needs_allow_expansive(summary.name)});
    EXPECT_EQ(p.ifs.size(), summary.maps);
    EXPECT_EQ(p.ifs.contraction(), summary.contraction);
    EXPECT_FALSE(summary.description.empty());
    EXPECT_FALSE(p.text.empty());
    if (needs_allow_expansive(summary.name)) {
      EXPECT_EQ(summary.contraction, 1.0);
    } else {
      EXPECT_LT(summary.contraction, 1.0);
      EXPECT_NO_THROW(load_ifs(summary.name));
    }
  }
}

TEST(shipped_presets, toml_names_match_their_file_names_and_super_presets_are_skipped) {
  const auto list = list_shipped_presets();
  for (const auto& file : shipped_files()) {
    const std::string name(file.name);
    const std::string stem = fs::path(name).stem().string();
    const bool listed =
        std::any_of(list.begin(), list.end(), [&](const auto& p) { return p.name == stem; });
    if (name.ends_with(".super.toml")) {
      EXPECT_FALSE(listed) << name;
    } else if (name.ends_with(".toml")) {
      EXPECT_TRUE(listed) << name;
      EXPECT_EQ(parse_ifs_toml(file.text, name).ifs.name, stem);
    }
  }
}

TEST(shipped_presets, the_swap_tilings_need_allow_expansive) {
  expect_error("square-tiling-2", ErrorKind::invalid_ifs,
               "shipped:square-tiling-2.toml: map 1: contraction factor must be < 1 (got 1); "
               "allow_expansive accepts it if the IFS contracts on average");
  expect_error("square-tiling-3", ErrorKind::invalid_ifs,
               "shipped:square-tiling-3.toml: map 1: contraction factor must be < 1 (got 1); "
               "allow_expansive accepts it if the IFS contracts on average");
}

TEST(shipped_presets, classic_coefficients_are_the_published_ones) {
  const Ifs fern = load_ifs("barnsley-fern").ifs;
  EXPECT_EQ(fern.maps, (std::vector<AffineMap>{{0, 0, 0, 0.16, 0, 0},
                                               {0.85, 0.04, -0.04, 0.85, 0, 1.6},
                                               {0.2, -0.26, 0.23, 0.22, 0, 1.6},
                                               {-0.15, 0.28, 0.26, 0.24, 0, 0.44}}));
  EXPECT_EQ(fern.probabilities, (std::vector<double>{0.01, 0.85, 0.07, 0.07}));
  EXPECT_EQ(load_ifs("right-sierpinski").ifs.maps,
            (std::vector<AffineMap>{
                {0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 0.5, 0}, {0.5, 0, 0, 0.5, 0, 0.5}}));
  // The equilateral triangle's maps fix its corners (0,0), (1,0), (1/2, √3/2).
  const Ifs triangle = load_ifs("sierpinski-triangle").ifs;
  const std::array<Point, 3> corners{{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}}};
  for (std::size_t n = 0; n < 3; ++n) {
    const Point q = triangle.maps[n](corners[n]);
    EXPECT_NEAR(q.x, corners[n].x, 1e-15);
    EXPECT_NEAR(q.y, corners[n].y, 1e-15);
    EXPECT_NEAR(triangle.maps[n].contraction(), 0.5, 1e-15);
  }
  // The Fractint fern is the same IFS as the native one.
  const Ifs fractint_fern = load_ifs("fern").ifs;
  EXPECT_EQ(fractint_fern.maps, fern.maps);
  EXPECT_EQ(fractint_fern.probabilities, fern.probabilities);
}

// The image of the unit square under an affine map: a parallelogram, corners in order.
std::array<Point, 4> image_of_unit_square(const AffineMap& f) {
  return {f({0, 0}), f({1, 0}), f({1, 1}), f({0, 1})};
}

// Separating axis test: convex polygons have disjoint interiors iff their projections on some
// edge normal overlap by no more than `eps`.
bool interiors_disjoint(const std::array<Point, 4>& p, const std::array<Point, 4>& q) {
  constexpr double eps = 1e-12;
  for (const auto* poly : {&p, &q})
    for (std::size_t i = 0; i < 4; ++i) {
      const Point a = (*poly)[i], b = (*poly)[(i + 1) % 4];
      const Point normal{b.y - a.y, a.x - b.x};
      auto range = [&](const std::array<Point, 4>& r) {
        double lo = INFINITY, hi = -INFINITY;
        for (const Point& v : r) {
          const double t = normal.x * v.x + normal.y * v.y;
          lo = std::min(lo, t), hi = std::max(hi, t);
        }
        return std::pair{lo, hi};
      };
      const auto [p_lo, p_hi] = range(p);
      const auto [q_lo, q_hi] = range(q);
      if (std::min(p_hi, q_hi) - std::max(p_lo, q_lo) <= eps) return true;
    }
  return false;
}

TEST(shipped_presets, square_tilings_tile_the_unit_square_in_raster_order) {
  // name, columns, rows of the tiling; map k is tile k in raster order from the bottom-left.
  const std::array<std::tuple<const char*, int, int>, 4> tilings{{{"square-tiling-2", 1, 2},
                                                                  {"square-tiling-3", 1, 3},
                                                                  {"square-tiling-4", 2, 2},
                                                                  {"square-tiling-9", 3, 3}}};
  for (const auto& [name, columns, rows] : tilings) {
    SCOPED_TRACE(name);
    const Ifs ifs = load_ifs(name, {.allow_expansive = true}).ifs;
    ASSERT_EQ(ifs.size(), static_cast<std::size_t>(columns * rows));
    double area = 0;
    for (std::size_t k = 0; k < ifs.size(); ++k) {
      const auto piece = image_of_unit_square(ifs.maps[k]);
      for (const Point& v : piece) {  // inside the square
        EXPECT_GE(v.x, -1e-15);
        EXPECT_LE(v.x, 1 + 1e-15);
        EXPECT_GE(v.y, -1e-15);
        EXPECT_LE(v.y, 1 + 1e-15);
      }
      area += std::abs(ifs.maps[k].det());
      for (std::size_t j = 0; j < k; ++j)
        EXPECT_TRUE(interiors_disjoint(piece, image_of_unit_square(ifs.maps[j])))
            << "pieces " << j << " and " << k << " overlap";
      const Point centre = ifs.maps[k]({0.5, 0.5});
      const int tile =
          static_cast<int>(centre.y * rows) * columns + static_cast<int>(centre.x * columns);
      EXPECT_EQ(tile, static_cast<int>(k));
    }
    // Pieces inside the square with disjoint interiors and total area 1 cover it.
    EXPECT_NEAR(area, 1.0, 1e-15);
  }
}

TEST(load_ifs, an_unknown_name_is_not_found_and_the_closest_name_is_suggested) {
  expect_error("fren", ErrorKind::not_found,
               "unknown preset 'fren': did you mean 'fern'? (see `ifsfx presets`)");
  expect_error("barnsly-fern", ErrorKind::not_found,
               "unknown preset 'barnsly-fern': did you mean 'barnsley-fern'? "
               "(see `ifsfx presets`)");
  expect_error("mandelbrot", ErrorKind::not_found,
               "unknown preset 'mandelbrot' (see `ifsfx presets`)");
}

TEST(load_ifs, a_missing_file_is_not_found_naming_its_path) {
  expect_error("no/such/fern.toml", ErrorKind::not_found, "no/such/fern.toml: no such file");
  expect_error("no/such/file.ifs:coral", ErrorKind::not_found, "no/such/file.ifs: no such file");
  expect_error("no/such/file.ifs", ErrorKind::not_found, "no/such/file.ifs: no such file");
}

TEST(load_ifs, names_ignore_case_and_shipped_files_are_found_by_file_name) {
  EXPECT_EQ(load_ifs("Coral").ifs.maps, load_ifs("coral").ifs.maps);
  EXPECT_EQ(load_ifs("barnsley-fern.toml").ifs.maps, load_ifs("barnsley-fern").ifs.maps);
  EXPECT_EQ(load_ifs("barnsley-fern").origin, "shipped:barnsley-fern.toml");
}

TEST(load_ifs, a_fractint_entry_is_named_as_file_colon_name) {
  const IfsPreset coral = load_ifs("fractint-classics.ifs:coral");
  EXPECT_EQ(coral.ifs.name, "coral");
  EXPECT_EQ(coral.origin, "shipped:fractint-classics.ifs:coral");
  EXPECT_EQ(coral.ifs.maps, load_ifs("coral").ifs.maps);
  EXPECT_EQ(coral.text.substr(0, 7), "coral {");
  EXPECT_EQ(load_ifs("fractint-classics.ifs").ifs.name, "binary");  // the first entry

  const TempDir dir;
  const std::string path = dir.write("two.ifs",
                                     "; two entries\n"
                                     "first { .5 0 0 .5 0 0 .5  .5 0 0 .5 1 0 .5 }\n"
                                     "second { .25 0 0 .25 0 0 }\n");
  EXPECT_EQ(load_ifs(path).ifs.name, "first");
  EXPECT_EQ(load_ifs(path + ":").ifs.name, "first");
  const IfsPreset second = load_ifs(path + ":second");
  EXPECT_EQ(second.ifs.maps, (std::vector<AffineMap>{{0.25, 0, 0, 0.25, 0, 0}}));
  EXPECT_EQ(second.origin, path + ":second");
  EXPECT_EQ(second.text, "second { .25 0 0 .25 0 0 }\n");
  expect_error(path + ":third", ErrorKind::not_found,
               path + ": no entry 'third' (entries: first, second)");
}

TEST(load_ifs, a_2d_entry_loads_from_a_file_with_3d_and_broken_entries) {
  const TempDir dir;
  const std::string path = dir.write("mixed.ifs",
                                     "solid (3D) { 0 0 0 0 0 0 0 0 0 0 0 0 1 }\n"
                                     "half { .5 0 0 .5 0 0 }\n"
                                     "odd { .5 0 0 .5 0 0 1 1 }\n");
  EXPECT_EQ(load_ifs(path + ":half").ifs.maps, (std::vector<AffineMap>{{0.5, 0, 0, 0.5, 0, 0}}));
  expect_error(path + ":solid", ErrorKind::unsupported,
               path + ":1: entry 'solid': only 2-D IFSs are supported (got a (3D) entry)");
  // Named without an entry, the first is taken; it cannot be used, so the message says which can.
  expect_error(path, ErrorKind::unsupported,
               path +
                   ":1: entry 'solid': only 2-D IFSs are supported (got a (3D) entry) (the first "
                   "of the file's 3 entries; name one as FILE.ifs:NAME, e.g. " +
                   path + ":half)");
  expect_error(path + ":odd", ErrorKind::parse,
               path +
                   ":3: entry 'odd': needs 7 numbers per map (a b c d e f p) or 6 "
                   "(a b c d e f) (got 8, a multiple of neither)");
  // parse_fractint reads the whole file, so it reports the first bad entry.
  EXPECT_THROW(parse_fractint("half { .5 0 0 .5 0 0 }\nsolid (3D) { 1 }\n", "x.ifs"), Error);
}

// Artists' files often open with notes in an entry of their own (Tony Hanmer's squares.ifs: 1375
// entries, the first `_README`, whose numbers make a map that does not contract). Named without
// an entry, such a file's message names the first entry that can be used.
TEST(load_ifs, a_file_opening_with_notes_names_an_entry_that_can_be_used) {
  const TempDir dir;
  const std::string path = dir.write("artist.ifs",
                                     "_README {     ; notes on this file\n"
                                     "1 1 1 1 1 1 1 ; a set of IFSs\n"
                                     "}\n"
                                     "flat { 1 0 0 1 0 0 1 }\n"
                                     "fine { .5 0 0 .5 0 0 .5  .5 0 0 .5 1 0 .5 }\n");
  const auto message_of = [](const std::string& spec) {
    try {
      load_ifs(spec);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string what = message_of(path);
  EXPECT_EQ(what.substr(0, path.size() + 9), path + ":_README:") << what;
  const std::string hint =
      " (the first of the file's 3 entries; name one as FILE.ifs:NAME, e.g. " + path + ":fine)";
  ASSERT_GE(what.size(), hint.size()) << what;
  EXPECT_EQ(what.substr(what.size() - hint.size()), hint) << "'flat' does not contract";
  EXPECT_EQ(load_ifs(path + ":fine").ifs.size(), 2u);
  // Named, an entry's own message stays as it is; so does that of a file of one entry.
  EXPECT_EQ(message_of(path + ":_README").find("(the first of"), std::string::npos);
  const std::string one = dir.write("one.ifs", "bad { 1 2 3 }\n");
  EXPECT_EQ(message_of(one),
            one +
                ":1: entry 'bad': needs 7 numbers per map (a b c d e f p) or 6 (a b c d e f) "
                "(got 3, a multiple of neither)");
}

TEST(list_presets_in, every_entry_of_a_fractint_file_with_why_it_cannot_be_used) {
  const TempDir dir;
  const std::string path = dir.write("artist.ifs",
                                     "_README { ; notes\n1 1 1 1 1 1 1\n}\n"
                                     "halves { ; two halves\n.5 0 0 .5 0 0 .5 .5 0 0 .5 1 0 .5\n}\n"
                                     "solid (3D) { 0 0 0 0 0 0 0 0 0 0 0 0 1 }\n");
  const auto list = list_presets_in(path);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].name, "_README");
  const std::string refused = path + ":_README: the IFS must contract on average";
  EXPECT_EQ(list[0].problem.substr(0, refused.size()), refused);
  EXPECT_EQ(list[1].name, "halves");
  EXPECT_TRUE(list[1].problem.empty()) << list[1].problem;
  EXPECT_EQ(list[1].maps, 2u);
  EXPECT_DOUBLE_EQ(list[1].contraction, 0.5);
  EXPECT_EQ(list[1].description, "two halves");
  EXPECT_EQ(list[2].problem,
            path + ":7: entry 'solid': only 2-D IFSs are supported (got a (3D) entry)");
  // What is listed as usable loads; what is not, does not, with the same message.
  EXPECT_EQ(load_ifs(path + ":halves").ifs.size(), 2u);
  expect_error(path + ":solid", ErrorKind::unsupported, list[2].problem);
  // A .toml file: its one preset.
  const auto fern = list_presets_in("barnsley-fern.toml");
  ASSERT_EQ(fern.size(), 1u);
  EXPECT_EQ(fern[0].maps, 4u);
  EXPECT_TRUE(fern[0].problem.empty());
}

// A designer's kind of Fractint entry: a point reflection (factor exactly 1) among three halves;
// it contracts on average (0.55 · log 1 + 0.45 · log ½ < 0).
constexpr const char* kReflection =
    "reflect { ; a point reflection\n"
    " -1  0  0 -1  0 10 .55\n"
    " .5  0  0 .5  0  0 .15\n"
    " .5  0  0 .5  0  5 .15\n"
    " .5  0  0 .5  5  0 .15\n"
    "}\n";

TEST(load_ifs, a_fractint_entry_contracting_on_average_loads_with_one_warning) {
  const TempDir dir;
  const std::string path = dir.write("designer.ifs", kReflection);
  const IfsPreset p = load_ifs(path);
  EXPECT_EQ(p.ifs.size(), 4u);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0], path +
                               ":reflect: map 1 does not contract (factor 1); accepted as Fractint "
                               "renders it, since the IFS contracts on average (mean log factor "
                               "-0.312)");
  // Accepted by the caller: nothing to say. Contractive entries: nothing either.
  EXPECT_TRUE(load_ifs(path, {.allow_expansive = true}).warnings.empty());
  EXPECT_TRUE(load_ifs("coral").warnings.empty());
}

TEST(load_ifs, a_fractint_entry_that_does_not_contract_on_average_is_refused) {
  const TempDir dir;
  const std::string path = dir.write("grow.ifs", "grow { 2.5 0 0 2.5 0 0 .5  .5 0 0 .5 1 0 .5 }\n");
  try {
    load_ifs(path);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
    const std::string start = path + ":grow: the IFS must contract on average: the mean";
    EXPECT_EQ(std::string(e.what()).substr(0, start.size()), start);
  }
}

TEST(load_ifs, a_toml_preset_stays_strict_unless_it_opts_in) {
  const TempDir dir;
  const std::string maps =
      "maps = [[-1, 0, 0, -1, 0, 10], [0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0, 5],\n"
      "        [0.5, 0, 0, 0.5, 5, 0]]\nprobabilities = [0.55, 0.15, 0.15, 0.15]\n";
  const std::string strict = dir.write("strict.toml", maps);
  expect_error(strict, ErrorKind::invalid_ifs,
               strict +
                   ": map 1: contraction factor must be < 1 (got 1); "
                   "allow_expansive accepts it if the IFS contracts on average");
  const IfsPreset opted = load_ifs(dir.write("opted.toml", "allow_expansive = true\n" + maps));
  EXPECT_TRUE(opted.allow_expansive);
  EXPECT_TRUE(opted.warnings.empty());
  const std::string bad = dir.write("bad.toml", "allow_expansive = \"yes\"\n" + maps);
  expect_error(bad, ErrorKind::parse,
               bad + ":1: allow_expansive: must be true or false (got a string)");
}

TEST(load_ifs, a_toml_file_is_read_and_validated_under_its_path) {
  const TempDir dir;
  const std::string text = "name = \"half\"\nmaps = [[0.5, 0, 0, 0.5, 0, 0]]\n";
  const std::string path = dir.write("half.toml", text);
  const IfsPreset p = load_ifs(path);
  EXPECT_EQ(p.origin, path);
  EXPECT_EQ(p.text, text);
  EXPECT_EQ(p.ifs.maps, (std::vector<AffineMap>{{0.5, 0, 0, 0.5, 0, 0}}));

  const std::string grow = dir.write("grow.toml", "maps = [[1.5, 0, 0, 0.5, 0, 0]]\n");
  expect_error(grow, ErrorKind::invalid_ifs,
               grow +
                   ": map 1: contraction factor must be < 1 (got 1.5); "
                   "allow_expansive accepts it if the IFS contracts on average");
  const std::string typo = dir.write("typo.toml", "maps = [[0.5, 0, 0, 0.5, 0]]\n");
  expect_error(typo, ErrorKind::parse, typo + ":1: map 1: needs 6 numbers a b c d e f (got 5)");
}

// A FractalDB category file (ifs/fractaldb_csv.h) is a preset too: named by its stem, its p
// normalised, its rows the maps in their order.
TEST(load_ifs, reads_a_fractaldb_category_csv) {
  const TempDir dir;
  const std::string path = dir.write(
      "00042.csv", "0.5,0,0,0.5,0,0,0.5\n0.5,0,0,0.5,0.5,0,0.25\n0.5,0,0,0.5,0,0.5,0.25\n");
  const IfsPreset p = load_ifs(path);
  EXPECT_EQ(p.format, PresetFormat::fractaldb);
  EXPECT_EQ(p.ifs.name, "00042");
  EXPECT_EQ(p.description, "FractalDB category 00042");
  EXPECT_EQ(p.origin, path);
  ASSERT_EQ(p.ifs.size(), 3u);
  EXPECT_EQ(p.ifs.maps[2], (AffineMap{0.5, 0, 0, 0.5, 0, 0.5}));
  EXPECT_EQ(p.ifs.probabilities, (std::vector<double>{0.5, 0.25, 0.25}));
  EXPECT_TRUE(p.warnings.empty());
  // A map that does not contract among ones that do: taken as FractalDB renders it, said once.
  const std::string mixed = dir.write("00007.csv", "-1,0,0,-1,0,0,0.1\n0.3,0,0,0.3,0.5,0,0.9\n");
  const IfsPreset m = load_ifs(mixed);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(
      m.warnings[0].find(mixed + ": map 1 does not contract (factor 1); accepted as FractalDB "
                                 "renders it"),
      std::string::npos)
      << m.warnings[0];
  // The file's own errors, with its name and line.
  const std::string bad = dir.write("00008.csv", "0.5,0,0,0.5,0,0,1\n0.5,0,0\n");
  try {
    load_ifs(bad);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::parse);
    EXPECT_EQ(std::string(e.what()).rfind(bad + ":2: ", 0), 0u) << e.what();
  }
}

TEST(load_ifs, rejects_other_files_and_superifs_presets) {
  expect_error("some/fern.txt", ErrorKind::unsupported,
               "some/fern.txt: preset files end in .toml, .ifs or .csv (a FractalDB category) "
               "(got none of them)");
  expect_error("mine.super.toml", ErrorKind::unsupported,
               "mine.super.toml: a superIFS preset, not an IFS (got a .super.toml file)");
  expect_error("", ErrorKind::invalid_argument,
               "preset: a preset name or a path is needed (got nothing)");
}

TEST(to_toml, round_trips_every_shipped_toml_preset) {
  for (const auto& file : shipped_files()) {
    const std::string name(file.name);
    if (!name.ends_with(".toml") || name.ends_with(".super.toml")) continue;
    SCOPED_TRACE(name);
    const IfsPreset p = parse_ifs_toml(file.text, name);
    const IfsPreset back = parse_ifs_toml(to_toml(p.ifs, p.description), name);
    EXPECT_EQ(back.ifs.name, p.ifs.name);
    EXPECT_EQ(back.ifs.maps, p.ifs.maps);
    EXPECT_EQ(back.ifs.probabilities, p.ifs.probabilities);
    EXPECT_EQ(back.ifs.colours, p.ifs.colours);
    EXPECT_EQ(back.description, p.description);
  }
}

}  // namespace
}  // namespace ifsfx
