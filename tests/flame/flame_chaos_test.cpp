// SPDX-License-Identifier: Apache-2.0
// A flame through ifsfx's chaos game: its attractor, tops and steal map. Oracles: a flame of plain
// linear xforms is its affine IFS, byte for byte in every mode; a final spherical xform inverts
// the attractor, p ↦ p / |p|², point for point.
#include "flame/flame_chaos.h"

#include <cmath>

#include <gtest/gtest.h>

#include "../common/known_ifs.h"
#include "../common/same_bytes.h"
#include "flame/variations.h"
#include "ifs/error.h"

namespace ifsfx::flame {
namespace {

VariationTerm term(const char* name, double weight = 1) {
  const Variation* v = find_variation(name);
  return {.id = v->id, .weight = weight, .params = default_parameters(*v)};
}

// The flame of an affine IFS: xform n is f_n seen in the flame plane, S∘f_n∘S with S(x, y) =
// (x, −y), `linear` of weight 1, the map's probability as weight.
Flame flame_of(const Ifs& F, Camera camera) {
  Flame flame;
  flame.name = F.name;
  flame.camera = camera;
  for (std::size_t n = 0; n < F.size(); ++n) {
    const AffineMap& f = F.maps[n];
    flame.xforms.push_back({.pre = {f.a, -f.b, -f.c, f.d, f.e, -f.f},
                            .weight = F.probabilities[n],
                            .variations = {term("linear")}});
  }
  return flame;
}

const Camera kFernCamera{.width = 64, .height = 56, .center = {0.25, -5}, .scale = 5.5};

TEST(flame_chaos, a_linear_flame_is_its_affine_ifs) {
  const Ifs F = testing::barnsley_fern();
  const Flame flame = flame_of(F, kFernCamera);
  const std::optional<Ifs> affine = affine_ifs(flame);
  ASSERT_TRUE(affine);
  EXPECT_EQ(affine->maps, F.maps);
  Flame post = flame;
  post.xforms[1].post = AffineMap{};
  EXPECT_FALSE(affine_ifs(post));
  Flame twice = flame;
  twice.xforms[2].variations = {term("linear", 0.5), term("linear", 0.5)};
  EXPECT_FALSE(affine_ifs(twice));
}

TEST(flame_chaos, a_linear_flame_gives_the_affine_pictures_byte_for_byte) {
  const Ifs F = testing::barnsley_fern();
  const Flame flame = flame_of(F, kFernCamera);
  const cv::Size size{64, 56};
  const Sampling flame_sampling{.quality = 4, .seed = 5, .threads = 2};
  Sampling ifs_sampling = flame_sampling;
  ifs_sampling.view = flame_viewport(flame, size).view;
  ifs_sampling.threads = 1;

  EXPECT_TRUE(testing::same_bytes(flame_attractor(flame, size, flame_sampling),
                                  render_attractor(F, size, {.sampling = ifs_sampling})));
  const Rgb grey{0.5, 0.5, 0.5};
  EXPECT_TRUE(testing::same_bytes(
      flame_tops(flame, size, {.sampling = flame_sampling, .exact = false, .second_symbol = true},
                 grey, true),
      tops_picture(F, size, {.sampling = ifs_sampling, .exact = false, .second_symbol = true}, grey,
                   true)));
  const Ifs G = default_colouring(F.size());
  const StealMap ours =
      flame_steal_map(flame, G, size, {.sampling = flame_sampling, .exact = false});
  const StealMap theirs = compute_steal_map(F, G, size, {.sampling = ifs_sampling, .exact = false});
  EXPECT_TRUE(testing::same_bytes(ours.coverage, theirs.coverage));
  EXPECT_TRUE(testing::same_bytes(ours.source_uv, theirs.source_uv));
  EXPECT_GT(cv::countNonZero(ours.coverage), 500);
}

// Four xforms halving [0.5, 1.5]² onto its quadrants (flame plane) and a final spherical xform:
// the picture is the square inverted, q = p / |p|², whose inverse is q / |q|² again.
Flame inverted_square() {
  Flame flame;
  flame.name = "inverted square";
  flame.camera = {.width = 48, .height = 48, .center = {0.8, 0.8}, .scale = 28};
  for (const double ty : {0.0, 0.5})
    for (const double tx : {0.0, 0.5})
      flame.xforms.push_back(
          {.pre = {0.5, 0, 0, 0.5, 0.25 + tx, 0.25 + ty}, .variations = {term("linear")}});
  flame.final_xform = Xform{.variations = {term("spherical")}};
  return flame;
}

// The colouring IFS that follows the square's quadrants onto the unit square (y up): T is then
// the inversion itself, shifted onto the unit square, uv = q / |q|² − (0.5, 0.5).
Ifs quadrants_of_the_source() {
  Ifs G;
  for (const double ty : {0.0, 0.5})
    for (const double tx : {0.0, 0.5}) G.maps.push_back({0.5, 0, 0, 0.5, tx, 0.5 - ty});
  return G;
}

TEST(flame_chaos, a_final_spherical_xform_inverts_the_attractor_and_the_steal_map) {
  const Flame flame = inverted_square();
  const cv::Size size{48, 48};
  const Sampling sampling{.quality = 16, .seed = 3};
  const StealMap T = flame_steal_map(flame, quadrants_of_the_source(), size,
                                     {.sampling = sampling, .exact = false});
  const TopSymbols tops = flame_top_symbols(flame, size, {.sampling = sampling, .exact = false});
  const Viewport vp = flame_viewport(flame, size);
  const double pixel = vp.view.width() / size.width;
  int inside = 0, covered_inside = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const Point x = vp.pixel_centre(c, r);
      const double r2 = x.x * x.x + x.y * x.y;
      const Point p{x.x / r2, -x.y / r2};  // the flame plane's preimage of the pixel centre
      // How far a point of the pixel may lie from p: the inversion stretches by 1 / |x|².
      const double reach = pixel / r2;
      const bool covered = T.coverage.at<std::uint8_t>(r, c) != 0;
      const double outside = std::max({0.5 - p.x, p.x - 1.5, 0.5 - p.y, p.y - 1.5});
      if (covered) {
        EXPECT_LT(outside, 1.5 * reach) << "pixel " << c << ", " << r;
        const cv::Vec2f uv = T.source_uv.at<cv::Vec2f>(r, c);
        EXPECT_NEAR(uv[0], p.x - 0.5, 1.5 * reach) << "pixel " << c << ", " << r;
        EXPECT_NEAR(uv[1], p.y - 0.5, 1.5 * reach) << "pixel " << c << ", " << r;
        // The top symbol is the quadrant of p, away from the quadrants' edges.
        if (std::abs(p.x - 1) > 1.5 * reach && std::abs(p.y - 1) > 1.5 * reach && outside < 0) {
          EXPECT_EQ(tops.first.at<std::uint16_t>(r, c), (p.x > 1 ? 1 : 0) + (p.y > 1 ? 2 : 0));
        }
      }
      if (outside < -1.5 * reach) {
        ++inside;
        covered_inside += covered;
      }
    }
  EXPECT_GT(inside, 150);
  EXPECT_GE(covered_inside, inside - inside / 100);
}

TEST(flame_chaos, a_flame_of_many_chunks_gives_the_same_bytes_for_any_thread_count) {
  // 48² pixels at quality 256: 589 824 points, three of the batched walk's chunks (2¹⁸ points
  // each), the last one of 64 walkers.
  const Flame flame = inverted_square();
  const cv::Size size{48, 48};
  const auto sampled = [](int threads) {
    return Sampling{.quality = 256, .seed = 7, .threads = threads};
  };
  const cv::Mat one = flame_attractor(flame, size, sampled(1));
  const TopSymbols tops = flame_top_symbols(flame, size, {.sampling = sampled(1), .exact = false});
  for (const int threads : {2, 3}) {
    EXPECT_TRUE(testing::same_bytes(one, flame_attractor(flame, size, sampled(threads))));
    const TopSymbols again =
        flame_top_symbols(flame, size, {.sampling = sampled(threads), .exact = false});
    EXPECT_TRUE(testing::same_bytes(tops.first, again.first));
    EXPECT_TRUE(testing::same_bytes(tops.second, again.second));
  }
}

// An xform that throws its points past the escape bound (weight 1/81 of the picks) adds nothing
// to the picture: its walkers start again. Had they stayed, the final spherical xform would put
// them at the origin, in view. A camera turned by 90° about the centre of a square raster draws
// the same walk's picture turned (pixel centres onto pixel centres; a point within rounding of a
// pixel's edge may land on either side).
TEST(flame_chaos, escaped_walkers_start_again_and_the_camera_turn_turns_the_picture) {
  const Flame flame = inverted_square();
  const cv::Size size{48, 48};
  const Sampling sampling{.quality = 16, .seed = 3};
  const cv::Mat plain = flame_attractor(flame, size, {.quality = 256, .seed = 3});
  Flame escaping = flame;
  escaping.xforms.push_back(
      {.pre = {1, 0, 0, 1, 1e11, 0}, .weight = 0.05, .variations = {term("linear")}});
  const cv::Mat escaped = flame_attractor(escaping, size, sampling);
  cv::Mat outside;
  cv::subtract(escaped, plain, outside);
  EXPECT_EQ(cv::countNonZero(outside), 0);
  EXPECT_GT(cv::countNonZero(escaped), cv::countNonZero(plain) * 9 / 10);

  Flame turned = flame;
  turned.camera.rotate = 90;
  const cv::Mat unturned = flame_attractor(flame, size, sampling);
  cv::Mat expected;
  cv::rotate(unturned, expected, cv::ROTATE_90_CLOCKWISE);
  cv::Mat differ;
  cv::compare(flame_attractor(turned, size, sampling), expected, differ, cv::CMP_NE);
  EXPECT_LT(cv::countNonZero(differ), cv::countNonZero(unturned) / 100);
  EXPECT_GT(cv::countNonZero(unturned), 300);
}

TEST(flame_chaos, a_flame_whose_orbits_always_escape_ends_with_an_empty_picture) {
  // One xform that moves every point by 1e11: each step escapes and restarts its walker, which
  // never plots. Both walks (the affine IFS's lanes, and the batched walk, which a term of
  // weight 0 selects) give up after kStepBudget times their steps instead of restarting for ever.
  Flame affine;
  affine.camera = {.width = 16, .height = 16, .center = {0, 0}, .scale = 8};
  affine.xforms.push_back({.pre = {1, 0, 0, 1, 1e11, 0}, .variations = {term("linear")}});
  Flame batched = affine;
  batched.xforms[0].variations.push_back(term("spherical", 0));
  ASSERT_TRUE(affine_ifs(affine).has_value());
  ASSERT_FALSE(affine_ifs(batched).has_value());
  // The points given up are not counted as plotted (the command's summary prints the count).
  for (const Flame& f : {affine, batched}) {
    RenderStats stats;
    EXPECT_EQ(cv::countNonZero(flame_attractor(f, {16, 16}, {.quality = 4, .seed = 1}, &stats)), 0);
    EXPECT_EQ(stats.points, 0u);
    const TopSymbols tops =
        flame_top_symbols(f, {16, 16}, {.sampling = {.quality = 4, .seed = 1}, .exact = false});
    EXPECT_EQ(cv::countNonZero(tops.coverage), 0);
    EXPECT_EQ(tops.points, 0u);
  }
  // A flame whose walkers plot every point counts them all: quality 4 on 16×16.
  Flame contracting = batched;
  contracting.xforms[0].pre = {0.5, 0, 0, 0.5, 0, 0};
  RenderStats stats;
  flame_attractor(contracting, {16, 16}, {.quality = 4, .seed = 1}, &stats);
  EXPECT_EQ(stats.points, 4u * 16 * 16);
}

TEST(flame_chaos, what_needs_inverse_maps_or_a_map_per_xform_is_refused) {
  const Flame flame = inverted_square();
  const auto message = [](auto&& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] {
              flame_top_symbols(flame, {16, 16}, {.exact = true});
            }),
            "exact: the exact descent follows inverse maps, and a flame's xforms have none; its "
            "tops and steal maps come from the chaos game (got a flame)");
  EXPECT_EQ(message([&] {
              flame_steal_map(flame, default_colouring(3), {16, 16}, {.exact = false});
            }),
            "colouring IFS: must have one map per xform of the flame (got 3 for 4)");
  EXPECT_EQ(message([&] {
              flame_attractor(flame, {16, 16}, {.seamless = true});
            }),
            "seamless: a flame is drawn in its own plane, not on the torus of a tile (got a "
            "flame)");
}

}  // namespace
}  // namespace ifsfx::flame
