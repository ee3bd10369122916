// SPDX-License-Identifier: Apache-2.0
#include "run/fractal_filter_options.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx::app {
namespace {

// The command's --preset and --colouring become the engine's data: F as load_ifs reads it, G
// fitted to the unit square as load_colouring fits it.
TEST(fractal_filter_args, settings_load_the_presets_as_data) {
  FractalFilterArgs args{.preset = "maple-leaf", .colouring = "maple-leaf", .view = "0,0,1,1"};
  const engine::FractalSettings s = args.settings();
  EXPECT_EQ(s.drawing, engine::Drawing(load_ifs("maple-leaf").ifs));
  ASSERT_TRUE(s.colouring.has_value());
  EXPECT_EQ(*s.colouring, load_colouring("maple-leaf", std::get<Ifs>(s.drawing)));
  ASSERT_TRUE(s.sampling.view.has_value());
  EXPECT_EQ(s.sampling.view->x1, 1);
  EXPECT_FALSE(FractalFilterArgs{}.settings().colouring.has_value());
  EXPECT_EQ(FractalFilterArgs{}.settings().drawing, engine::Drawing(engine::default_drawing()));
}

TEST(fractal_filter_args, bad_presets_fail_naming_them) {
  EXPECT_THROW(FractalFilterArgs{.preset = "no-such-preset"}.settings(), Error);
  try {
    FractalFilterArgs{.preset = "barnsley-fern", .colouring = "sierpinski-triangle"}.settings();
    FAIL() << "a 3-map colouring of a 4-map IFS was accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "colouring: sierpinski-triangle must have as many maps as barnsley-fern (got 3 "
                 "for 4)");
  }
}

// A Fractint entry that contracts only on average (a point reflection, factor 1) is drawn as
// Fractint draws it; load_ifs's one warning line goes to the caller, which prints it.
TEST(fractal_filter_args, hands_on_the_warning_of_a_fractint_entry_contracting_on_average) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("fractal_filter_args_reflect-" + std::to_string(getpid()) + ".ifs");
  std::ofstream(file) << "reflect {\n -1 0 0 -1 0 10 .55\n .5 0 0 .5 0 0 .15\n"
                         " .5 0 0 .5 0 5 .15\n .5 0 0 .5 5 0 .15\n}\n";
  std::vector<std::string> warnings;
  const engine::FractalSettings s =
      FractalFilterArgs{.preset = file.string() + ":reflect"}.settings(&warnings);
  std::filesystem::remove(file);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(":reflect: map 1 does not contract (factor 1); accepted as "
                             "Fractint renders it"),
            std::string::npos)
      << warnings[0];
  EXPECT_EQ(engine::map_count(s.drawing), 4u);
  std::vector<std::string> none;
  FractalFilterArgs{}.settings(&none);
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace ifsfx::app
