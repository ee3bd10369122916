// SPDX-License-Identifier: Apache-2.0
// Termination of the computations over IFS geometry (issue 12): absurd IFSs are refused up front
// or framed in finite, resolvable numbers, and rendered in bounded time.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "ifs/chaos_game.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "ifs/view.h"
#include "known_ifs.h"

namespace ifsfx {
namespace {

// Three half-size maps, two of them translated by `t` (the 1e40 and 1e308).
Ifs translated(double t) {
  return {"translated",
          {{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, t, 0}, {0.5, 0, 0, 0.5, 0, t}},
          {},
          {}};
}

std::string invalid_ifs_message(const Ifs& ifs) {
  try {
    validate(ifs, ifs.name);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_ifs);
    return e.what();
  }
  return "<accepted>";
}

TEST(geometry_limits, coefficients_beyond_the_plane_are_refused) {
  EXPECT_EQ(invalid_ifs_message(translated(1e308)),
            "translated: map 2: coefficients must lie within ±1e+100 (got 1e+308)");
  EXPECT_EQ(invalid_ifs_message(translated(-1e101)),
            "translated: map 2: coefficients must lie within ±1e+100 (got -1e+101)");
}

TEST(geometry_limits, an_attractor_reaching_beyond_the_plane_is_refused) {
  // Factor 1 − 1e-7 and a translation of 1e95: the fixed point alone lies at 1e102.
  const Ifs slow{"slow", {{0.9999999, 0, 0, 0.9999999, 1e95, 0}, {0.5, 0, 0, 0.5, 0, 0}}, {}, {}};
  EXPECT_EQ(invalid_ifs_message(slow).rfind("slow: the attractor would reach ", 0), 0u)
      << invalid_ifs_message(slow);
  EXPECT_NE(invalid_ifs_message(slow).find(" from the origin, beyond ±1e+100: its translations are "
                                           "too large for its factors (scale the IFS down)"),
            std::string::npos);
  EXPECT_EQ(invalid_ifs_message(translated(4e99)), "<accepted>");  // reaches 8e99
  EXPECT_EQ(invalid_ifs_message(translated(6e99)).rfind("translated: the attractor would reach", 0),
            0u);
}

// Huge translations, tiny factors, attractors that are a point or a few points, all-singular
// maps: each is framed in finite, resolvable numbers and rendered exactly, in bounded time.
TEST(geometry_limits, absurd_but_valid_ifss_are_framed_and_rendered) {
  const std::vector<Ifs> cases{
      translated(1e40),
      translated(4e99),
      {"tiny", {{1e-300, 0, 0, 1e-300, 0, 0}, {1e-300, 0, 0, 1e-300, 1, 0}}, {}, {}},
      {"subnormal", {{0.5, 0, 0, 0.5, 0, 0}, {0.5, 0, 0, 0.5, 5e-324, 0}}, {}, {}},
      {"point", {{0.5, 0, 0, 0.5, 0, 0}, {0.3, 0, 0, 0.3, 0, 0}}, {}, {}},
      {"far-point", {{0.5, 0, 0, 0.5, 5e98, 5e98}, {0.25, 0, 0, 0.25, 7.5e98, 7.5e98}}, {}, {}},
      {"singular", {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 1}}, {}, {}},
      // Invertible by a hair (det 1.2e-12): the inverses expand the plane by 1e6 a level.
      {"thin",
       {{1.1e-6, 0, 0, 1.1e-6, 0, 0}, {1.1e-6, 0, 0, 1.1e-6, 1, 0}, {1.1e-6, 0, 0, 1.1e-6, 0, 1}},
       {},
       {}},
  };
  for (const Ifs& ifs : cases) {
    SCOPED_TRACE(ifs.name);
    ASSERT_NO_THROW(validate(ifs, ifs.name));
    const Box bounds = attractor_bounds(ifs);
    const Box view = fit_view(bounds, {32, 32});
    for (const double x : {view.x0, view.y0, view.x1, view.y1}) EXPECT_TRUE(std::isfinite(x));
    const double magnitude =
        std::max({std::abs(view.x0), std::abs(view.x1), std::abs(view.y0), std::abs(view.y1)});
    EXPECT_GE(view.width(), kMinRelativeExtent * magnitude);
    EXPECT_GE(view.width(), 1e-100);
    const TopSymbols tops = top_symbols(ifs, {32, 32}, {.exact = true});
    EXPECT_GT(cv::countNonZero(tops.coverage), 0);
    const StealMap map =
        compute_steal_map(ifs, default_colouring(ifs.size()), {32, 32}, {.exact = true});
    EXPECT_GT(cv::countNonZero(map.coverage), 0);
  }
}

TEST(geometry_limits, unresolvable_views_are_refused) {
  for (const char* view : {"0,0,1e-300,1e-300", "1e9,0,1.0000000000001e9,1",
                           "-1e308,-1e308,1e308,1e308", "0,0,1e101,1"}) {
    SCOPED_TRACE(view);
    try {
      parse_box(view, "--view");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
      EXPECT_EQ(std::string(e.what()).rfind("--view: ", 0), 0u) << e.what();
    }
  }
  EXPECT_NO_THROW(parse_box("0.5,0.5,0.5000001,0.5000001"));  // a deep zoom is fine
}

TEST(geometry_limits, quality_is_bounded) {
  const Ifs fern = testing::barnsley_fern();
  EXPECT_THROW(render_measure(fern, {8, 8}, {.sampling = {.quality = 1e300}}), Error);
  EXPECT_THROW(
      top_symbols(fern, {8, 8}, {.sampling = {.quality = kMaxQuality * 2}, .exact = false}), Error);
  EXPECT_THROW(compute_steal_map(fern, default_colouring(4), {8, 8},
                                 {.sampling = {.quality = NAN}, .exact = false}),
               Error);
}

}  // namespace
}  // namespace ifsfx
