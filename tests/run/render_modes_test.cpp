// SPDX-License-Identifier: Apache-2.0
#include "run/render_modes.h"

#include <string>

#include <gtest/gtest.h>

#include "ifs/error.h"

namespace ifsfx::app {
namespace {

std::string refusal(RenderMode mode, const ModeOptions& options, const std::string& word) {
  try {
    check_mode_options(mode, options, word);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    return e.what();
  }
  return "";
}

TEST(render_modes, names_round_trip_in_the_order_of_the_help) {
  EXPECT_EQ(render_mode_names(), "attractor, measure, tops or steal");
  for (const RenderModeInfo& info : render_modes()) {
    EXPECT_EQ(parse_render_mode(info.name), info.mode);
    EXPECT_STREQ(to_string(info.mode), info.name);
  }
  EXPECT_EQ(parse_render_mode("TOPS"), RenderMode::tops);
}

TEST(render_modes, an_unknown_mode_names_the_modes) {
  try {
    parse_render_mode("fire", "mode");
    FAIL() << "'fire' was taken for a mode";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "mode: attractor, measure, tops or steal (got 'fire')");
  }
}

TEST(render_modes, refuses_what_a_mode_would_ignore_in_the_doors_words) {
  EXPECT_EQ(refusal(RenderMode::tops, {.source = {"--source", true}}, "--mode"),
            "--source: only with --mode steal (got --mode tops)");
  EXPECT_EQ(refusal(RenderMode::measure, {.map_method = {"--exact/--chaos", true}}, "--mode"),
            "--exact/--chaos: only with --mode tops or steal (got --mode measure)");
  EXPECT_EQ(refusal(RenderMode::steal, {.second_symbol = {"second_symbol", true}}, "mode"),
            "second_symbol: only with mode tops (got mode steal)");
  EXPECT_EQ(refusal(RenderMode::attractor, {.background = {"--background", true}}, "--mode"),
            "--background: only with --mode tops or steal (got --mode attractor)");
}

TEST(render_modes, the_steal_mode_needs_a_source) {
  EXPECT_EQ(refusal(RenderMode::steal, {.source = {"source", false}}, "mode"),
            "source: mode steal needs a source image");
  EXPECT_EQ(refusal(RenderMode::steal,
                    {.source = {"--source", true}, .colouring = {"--colouring", true}}, "--mode"),
            "");
  EXPECT_EQ(refusal(RenderMode::tops, {.second_symbol = {"--second-symbol", true}}, "--mode"), "");
}

}  // namespace
}  // namespace ifsfx::app
