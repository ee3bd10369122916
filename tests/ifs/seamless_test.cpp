// SPDX-License-Identifier: Apache-2.0
// IFSs on the torus of the tile (docs/design.md §11): every map followed by the wrap back into the
// view. The chaos game keeps every point in the tile; where a wrapped piece overlaps another, the
// higher map is on top (eq. 7), by the exact descent and by the chaos game alike, also where the
// wrap gives a pixel two preimages under one map; the identity pair still returns the source bit
// for bit; nothing depends on the thread count; and the shipped presets offered as seamless tiles
// have no seam (the seam statistic of tests/common/seam.h at most 1.15, in every mode).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/preset.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tiles.h"
#include "ifs/tops.h"
#include "same_bytes.h"
#include "seam.h"
#include "tests/ifs/steal_test_ifs.h"

namespace ifsfx {
namespace {

const Box kUnit{0, 0, 1, 1};

// The four quadrants of the unit square with the top-right one moved a quarter to the right: on
// the torus of the unit tile its piece [3/4, 5/4) × [1/2, 1) wraps onto [0, 1/4) × [1/2, 1), over
// the top-left quadrant's piece (map 2). Level 1 leaves [1/2, 3/4) × [1/2, 1) empty.
Ifs wrapped_quadrants() {
  Ifs f;
  f.name = "wrapped-quadrants";
  f.maps = {{0.5, 0, 0, 0.5, 0, 0},
            {0.5, 0, 0, 0.5, 0.5, 0},
            {0.5, 0, 0, 0.5, 0, 0.5},
            {0.5, 0, 0, 0.5, 0.75, 0.5}};
  return f;
}

// Map 0 turns by 45° and shrinks by 3/4: it takes the unit tile to a diamond 1.06 wide, so a pixel
// near the diamond's left or right corner lies in it twice, by two translates of the lattice, and
// has two preimages under map 0. Map 2 wraps across the top-right corner.
Ifs turned() {
  Ifs f;
  f.name = "turned";
  const double k = 0.75 / std::sqrt(2.0);
  f.maps = {{k, -k, k, k, 0.5, 0.05}, {0.5, 0, 0, 0.5, 0.45, 0.0}, {0.45, 0, 0, 0.45, 0.8, 0.7}};
  return f;
}

// The pixels of `tops` in the plane rectangle `where` of the unit tile, by first symbol (index N:
// not covered).
std::vector<int> symbols_in(const TopSymbols& tops, const Box& where, std::size_t maps) {
  std::vector<int> count(maps + 1, 0);
  const cv::Size size = tops.coverage.size();
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const double x = (c + 0.5) / size.width, y = 1 - (r + 0.5) / size.height;
      if (x < where.x0 || x >= where.x1 || y < where.y0 || y >= where.y1) continue;
      ++count[tops.coverage.at<std::uint8_t>(r, c) ? tops.first.at<std::uint16_t>(r, c) : maps];
    }
  return count;
}

// Of the pixels both cover, the share where the chaos game's first symbol is the exact one.
double agreement(const TopSymbols& chaos, const TopSymbols& exact) {
  int both = 0, same = 0;
  for (int r = 0; r < exact.first.rows; ++r)
    for (int c = 0; c < exact.first.cols; ++c) {
      if (!chaos.coverage.at<std::uint8_t>(r, c) || !exact.coverage.at<std::uint8_t>(r, c))
        continue;
      ++both;
      same += chaos.first.at<std::uint16_t>(r, c) == exact.first.at<std::uint16_t>(r, c);
    }
  EXPECT_GT(both, 1000);
  return both > 0 ? static_cast<double>(same) / both : 0;
}

TEST(seamless, every_chaos_game_point_lands_in_the_tile) {
  // A view inside the attractor's box: off the torus most points would fall outside it.
  const Ifs fern = testing::fern();
  const Box b = attractor_bounds(fern);
  const Viewport torus{{b.x0 + 0.3 * b.width(), b.y0 + 0.2 * b.height(), b.x1 - 0.25 * b.width(),
                        b.y1 - 0.4 * b.height()},
                       {97, 61},
                       true};
  const std::uint64_t points = 3'000'017;
  const cv::Mat counts = visit_counts(fern, torus, points, {.seed = 3});
  EXPECT_EQ(cv::sum(counts)[0], static_cast<double>(points));
  const cv::Mat plane = visit_counts(fern, {torus.view, torus.size}, points, {.seed = 3});
  EXPECT_LT(cv::sum(plane)[0], 0.5 * static_cast<double>(points));
}

TEST(seamless, a_wrapped_piece_is_on_top_where_it_overlaps_a_lower_one) {
  const Ifs F = wrapped_quadrants();
  const cv::Size size{128, 128};
  const TopSymbols exact = top_symbols(F, size, {.sampling = {.view = kUnit, .seamless = true}});
  const TopSymbols chaos = top_symbols(
      F, size, {.sampling = {.view = kUnit, .quality = 64, .seamless = true}, .exact = false});
  for (const TopSymbols* tops : {&exact, &chaos}) {
    const char* how = tops == &exact ? "exact" : "chaos game";
    // Map 3's piece wrapped onto the left edge lies over map 2's: 3 on top there, ...
    const auto over = symbols_in(*tops, {0.02, 0.52, 0.23, 0.73}, 4);
    EXPECT_GT(over[3], 300) << how;
    EXPECT_LE(over[0] + over[1] + over[2], over[3] / 50) << how;
    // ... map 2 alone to its right, map 3 alone on the right edge, nothing in the level-1 hole.
    const auto left = symbols_in(*tops, {0.27, 0.52, 0.48, 0.98}, 4);
    EXPECT_GT(left[2], 500) << how;
    EXPECT_LE(left[0] + left[1] + left[3], left[2] / 50) << how;
    const auto right = symbols_in(*tops, {0.77, 0.52, 0.98, 0.98}, 4);
    EXPECT_GT(right[3], 500) << how;
    EXPECT_LE(right[0] + right[1] + right[2], right[3] / 50) << how;
    const auto hole = symbols_in(*tops, {0.52, 0.52, 0.73, 0.98}, 4);
    EXPECT_LE(hole[0] + hole[1] + hole[2] + hole[3], hole[4] / 50) << how;
  }
  EXPECT_GE(agreement(chaos, exact), 0.98);
}

TEST(seamless, the_descent_follows_every_preimage_the_wrap_creates) {
  const Ifs F = turned();
  const cv::Size size{256, 256};
  const TopSymbols exact = top_symbols(F, size, {.sampling = {.view = kUnit, .seamless = true}});
  const TopSymbols chaos = top_symbols(
      F, size, {.sampling = {.view = kUnit, .quality = 64, .seamless = true}, .exact = false});
  EXPECT_GE(agreement(chaos, exact), 0.97);
  EXPECT_GE(cv::countNonZero(exact.coverage), 0.9 * cv::countNonZero(chaos.coverage));
}

TEST(seamless, identity_pair_on_the_torus_returns_the_source_exactly) {
  const cv::Mat source = read_image(testing::photo_path()).pixels;
  for (int k : {2, 3}) {
    const Ifs t = testing::square_tiling(k);
    const StealMap map =
        compute_steal_map(t, t, source.size(), {.sampling = {.view = kUnit, .seamless = true}});
    EXPECT_EQ(cv::countNonZero(map.coverage), source.size().area()) << k * k << " maps";
    EXPECT_EQ(cv::norm(apply(map, source), source, cv::NORM_INF), 0) << k * k << " maps";
    // Two by two periods of it: the source repeated.
    cv::Mat repeated;
    cv::repeat(source, 2, 2, repeated);
    EXPECT_TRUE(testing::same_bytes(apply(tile_picture(map, {.tiles = {2, 2}}), source), repeated));
    // By the chaos game: within half a pixel, as off the torus.
    const StealMap chaos = compute_steal_map(
        t, t, source.size(),
        {.sampling = {.view = kUnit, .quality = 16, .seamless = true}, .exact = false});
    EXPECT_GE(testing::psnr(apply(chaos, source), source), 27) << k * k << " maps";
  }
}

// The torus of a tile inside the attractor's box, where the maps wrap.
Box inner_tile(const Ifs& F) {
  const Box b = attractor_bounds(F);
  return {b.x0 + 0.1 * b.width(), b.y0 + 0.15 * b.height(), b.x1 - 0.1 * b.width(),
          b.y1 - 0.05 * b.height()};
}

cv::Mat steal_map_bytes(const StealMap& map) {
  cv::Mat coverage, out;
  map.coverage.convertTo(coverage, CV_32F);
  cv::merge(std::vector<cv::Mat>{map.source_uv, coverage}, out);
  return out;
}

TEST(seamless, no_mode_depends_on_the_thread_count) {
  for (const Ifs& F : {testing::fern(), turned(), load_ifs("twin-dragon").ifs}) {
    const cv::Size size{256, 192};  // at 200 points per pixel, 3 chunks of the chaos game
    const Box view = inner_tile(F);
    const Ifs G = default_colouring(F.size());
    const auto all_modes = [&](int threads) {
      std::vector<cv::Mat> out;
      const RenderOptions r{
          .sampling = {.view = view, .quality = 200, .threads = threads, .seamless = true},
          .supersample = 2};
      out.push_back(render_attractor(F, size, r));
      out.push_back(render_measure(F, size, r));
      for (const bool exact : {false, true}) {
        out.push_back(render_tops(
            F, size,
            {.sampling = {.view = view, .quality = 200, .threads = threads, .seamless = true},
             .exact = exact,
             .second_symbol = true}));
        out.push_back(steal_map_bytes(compute_steal_map(
            F, G, size,
            {.sampling = {.view = view, .quality = 200, .threads = threads, .seamless = true},
             .exact = exact})));
      }
      return out;
    };
    const auto one = all_modes(1), three = all_modes(3);
    for (std::size_t i = 0; i < one.size(); ++i)
      EXPECT_TRUE(testing::same_bytes(one[i], three[i])) << F.name << ", output " << i;
  }
}

// The shipped presets offered as seamless tiles, rendered as `ifsfx render --seamless` renders
// them (the preset's tile, else its attractor framed with no margin; its offset), in every mode:
// the seam statistic at most 1.15 (a seam shows as several times the interior's difference).
TEST(seamless, shipped_presets_offered_as_seamless_tiles_have_no_seam) {
  const cv::Size size{192, 192};
  const cv::Mat photo = read_image(testing::photo_path()).pixels;
  int offered = 0;
  for (const PresetSummary& summary : list_shipped_presets()) {
    if (!summary.seamless) continue;
    ++offered;
    const IfsPreset preset = load_ifs(summary.name);
    const Ifs& F = preset.ifs;
    const Box view =
        preset.seamless->view ? *preset.seamless->view : fit_view(attractor_bounds(F), size, 0);
    const TileLayout layout{.offset = preset.seamless->offset};
    const Sampling sampling{.view = view, .seamless = true};
    const RenderOptions r{.sampling = sampling};
    const TopsOptions t{.sampling = sampling};
    const StealMapOptions s{.sampling = sampling};
    const std::vector<std::pair<std::string, cv::Mat>> pictures = {
        {"attractor", render_attractor(F, size, r)},
        {"measure", render_measure(F, size, r)},
        {"tops", render_tops(F, size, t)},
        {"steal", apply(compute_steal_map(F, default_colouring(F.size()), size, s), photo)},
    };
    for (const auto& [mode, tile] : pictures) {
      const testing::SeamStatistic seam = testing::seam_statistic(tile_picture(tile, layout));
      EXPECT_LE(seam.ratio(), 1.15) << summary.name << ", " << mode << ": across the edges "
                                    << seam.across_edges << ", inside " << seam.inside;
    }
  }
  EXPECT_GE(offered, 2);
}

}  // namespace
}  // namespace ifsfx
