// SPDX-License-Identifier: Apache-2.0
// SuperIFS buffers and textures on the torus of their rectangle (docs/design.md §11): each piece of
// a buffer is the wrapped image of the buffer it came from and nothing else; the descent follows
// the wrapped preimages exactly (against plain double arithmetic, and against the IFS core's
// descent on the torus, where the wrap gives a pixel two preimages under one map); the identity
// pair still returns the source; the measure keeps its mass; nothing depends on the thread count;
// and the shipped superIFS presets offered as seamless tiles have no seam in any mode.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ifs/image_io.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tiles.h"
#include "same_bytes.h"
#include "seam.h"
#include "superifs/buffers.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"
#include "superifs_fixtures.h"

namespace ifsfx {
namespace {

using testing::square_grid;

const Box kUnit{0, 0, 1, 1};

// The quadrant tiling moved a quarter of the square to the right: on the torus of the unit square
// its pieces still tile it, but the two on the right wrap across the edge.
Ifs moved_quadrants() {
  Ifs f = square_grid(2);
  f.name = "moved-quadrants";
  for (auto& m : f.maps) m.e += 0.25;
  return f;
}

// Four corners of factor 0.4 moved so that two of them wrap: dust on the torus.
Ifs moved_dust() {
  Ifs f;
  f.name = "moved-dust";
  for (const Point t : {Point{0.1, 0.05}, Point{0.7, 0.05}, Point{0.1, 0.75}, Point{0.7, 0.75}})
    f.maps.push_back({0.4, 0, 0, 0.4, t.x, t.y});
  return f;
}

// The wrapped forward image of the set pixels of `previous` under f: wrap(f(centre)), pixel
// coordinates mod the raster (an oracle independent of the inverse-mapping raster).
cv::Mat wrapped_forward_image(const cv::Mat& previous, const AffineMap& f, const Viewport& vp) {
  cv::Mat out(previous.size(), CV_8UC1, cv::Scalar(0));
  for (int row = 0; row < previous.rows; ++row)
    for (int col = 0; col < previous.cols; ++col) {
      if (!previous.at<uchar>(row, col)) continue;
      const Point y = vp.to_pixel(f(vp.pixel_centre(col, row)));
      const int c = static_cast<int>(std::floor(y.x)), q = static_cast<int>(std::floor(y.y));
      out.at<uchar>(((q % out.rows) + out.rows) % out.rows,
                    ((c % out.cols) + out.cols) % out.cols) = 255;
    }
  return out;
}

// `mask` dilated by a w×w square on the torus: across the edges too.
cv::Mat dilated_on_torus(const cv::Mat& mask, int w) {
  cv::Mat padded, d;
  cv::copyMakeBorder(mask, padded, w, w, w, w, cv::BORDER_WRAP);
  cv::dilate(padded, d, cv::Mat::ones(w, w, CV_8U));
  return d(cv::Rect(w, w, mask.cols, mask.rows)).clone();
}

double contained(const cv::Mat& part, const cv::Mat& whole) {
  cv::Mat both;
  cv::bitwise_and(part, whole, both);
  return static_cast<double>(cv::countNonZero(both)) / std::max(1, cv::countNonZero(part));
}

TEST(seamless_buffers, every_piece_is_the_wrapped_image_of_its_buffer) {
  SuperIfs s;
  s.ifs = {moved_quadrants(), moved_dust()};
  s.view = kUnit;
  const cv::Size size{160, 128};
  Buffers k(s, size, {.count = 1, .sampling = {.seed = 5, .seamless = true}});
  k.run(5);
  for (int step = 0; step < 4; ++step) {
    const cv::Mat before = k.mask(0).clone();
    k.step();
    const std::uint32_t n = k.last_choices().ifs[0];
    cv::Mat pieces(size, CV_8UC1, cv::Scalar(0));
    for (std::size_t m = 0; m < 4; ++m) {
      const cv::Mat piece = wrapped_forward_image(before, s.ifs[n].maps[m], k.viewport());
      EXPECT_GE(contained(piece, k.mask(0)), 0.999) << "step " << step << " piece " << m;
      pieces |= piece;
    }
    // Nothing but the pieces, up to the conservative lookup's margin, across the edges too.
    const cv::Mat near = dilated_on_torus(pieces, 2 * k.dilation() + 3);
    EXPECT_EQ(cv::countNonZero(k.mask(0) & ~near), 0) << "step " << step;
  }
}

TEST(seamless_buffers, one_ifs_gives_its_attractor_on_the_torus) {
  SuperIfs s;
  s.ifs = {moved_dust()};
  s.view = kUnit;
  const cv::Size size{192, 192};
  Buffers k(s, size, {.count = 2, .sampling = {.seamless = true}});
  k.run(default_steps(s, size));
  // Every point of the chaos game on the torus lies in the set, which is the fattened attractor.
  const cv::Mat points =
      render_attractor(s.ifs[0], size, {.sampling = {.view = kUnit, .seamless = true}});
  for (std::size_t v = 0; v < 2; ++v) {
    EXPECT_GE(contained(points, k.mask(v)), 0.999) << "buffer " << v;
    EXPECT_EQ(cv::countNonZero(k.mask(v) & ~dilated_on_torus(points, 2 * k.dilation() + 3)), 0);
  }
  // The dust wraps: a buffer holds pixels on both sides of each edge of the tile.
  EXPECT_GT(cv::countNonZero(k.mask(0).col(0)), 0);
  EXPECT_GT(cv::countNonZero(k.mask(0).col(size.width - 1)), 0);
}

TEST(seamless_buffers, the_measure_keeps_its_mass_on_the_torus) {
  SuperIfs s;
  s.ifs = {moved_quadrants(), moved_dust()};
  s.view = kUnit;
  Buffers k(s, {96, 96}, {.count = 2, .sampling = {.seamless = true}, .density = true});
  k.run(10);
  for (std::size_t v = 0; v < 2; ++v) {
    EXPECT_NEAR(cv::sum(k.density(v))[0], 1.0, 1e-5);
    cv::Mat off;
    cv::bitwise_and(k.density(v) > 0, k.mask(v) == 0, off);
    EXPECT_EQ(cv::countNonZero(off), 0) << "mass off the set in buffer " << v;
  }
}

// T(x) for an IFS whose attractor is the whole torus of the unit square, in plain double
// arithmetic, by the rule of eq. 7 on the torus: every translate x + λ whose preimage lies in the
// square [0, 1)² is a preimage; the top address is the largest over all of them, so the candidates
// whose addresses agree so far are all followed (at most 8), each level taking the highest m that
// any of them has. The word of the first candidate at the end.
Point reference_steal(const Ifs& f, const Ifs& g, Point x, int levels = 40) {
  struct Candidate {
    Point y;
    std::vector<std::size_t> word;
  };
  std::vector<Candidate> now{{x, {}}};
  for (int level = 0; level < levels; ++level) {
    std::vector<Candidate> next;
    for (std::size_t m = f.size(); m-- > 0 && next.empty();)
      for (const Candidate& c : now)
        for (int i = -2; i <= 2; ++i)
          for (int j = -2; j <= 2; ++j) {
            const Point y = (*f.maps[m].inverse())({c.y.x + i, c.y.y + j});
            if (y.x >= 0 && y.y >= 0 && y.x < 1 && y.y < 1 && next.size() < 8) {
              next.push_back({y, c.word});
              next.back().word.push_back(m);
            }
          }
    if (next.empty()) break;
    now = std::move(next);
  }
  Point t = now[0].y;
  for (std::size_t i = now[0].word.size(); i-- > 0;) t = g.maps[now[0].word[i]](t);
  return t;
}

// The largest distance between T(x) of two steal maps and the reference at each pixel centre, and
// the share of pixels where both are within `tolerance` of it.
struct Distance {
  double worst = 0, close = 0;
};
Distance distance(const StealMap& map, const Ifs& f, const Ifs& g, double tolerance) {
  const cv::Size size = map.size();
  int close = 0;
  Distance d;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      const Point t = reference_steal(f, g, {(c + 0.5) / size.width, 1 - (r + 0.5) / size.height});
      const cv::Vec2f uv = map.source_uv.at<cv::Vec2f>(r, c);
      const double far = std::max(std::abs(uv[0] - t.x), std::abs(uv[1] - (1 - t.y)));
      d.worst = std::max(d.worst, far);
      close += far < tolerance;
    }
  d.close = static_cast<double>(close) / size.area();
  return d;
}

TEST(seamless_texture, one_ifs_one_buffer_steals_like_exact_arithmetic_on_the_torus) {
  // The quadrants moved across the edge tile the torus; sizes of powers of two keep the pixel
  // centres' preimages exact, so the pixels that land on the pieces' edges decide alike here and
  // in the reference.
  SuperIfs s;
  s.ifs = {moved_quadrants()};
  s.view = kUnit;
  const cv::Size size{128, 64};
  Buffers k(s, size, {.count = 1, .sampling = {.seamless = true}, .history = 30});
  k.run(30);
  const StealMap mine = steal_map(k, 0);
  EXPECT_EQ(cv::countNonZero(mine.coverage), size.area());
  const Ifs g = colouring_ifs(s, 0);
  EXPECT_LT(distance(mine, s.ifs[0], g, 1e-5).worst, 1e-5);
  // The IFS core's exact descent on the torus, too.
  const StealMap core =
      compute_steal_map(s.ifs[0], g, size, {.sampling = {.view = kUnit, .seamless = true}});
  EXPECT_EQ(cv::countNonZero(core.coverage), size.area());
  EXPECT_LT(distance(core, s.ifs[0], g, 1e-5).worst, 1e-5);
}

TEST(seamless_texture, the_descent_follows_both_preimages_where_the_wrap_gives_two) {
  // The quadrants tile the torus; a fifth map on top turns by 45° and shrinks by 0.85, and its
  // piece, a diamond 1.2 wide, overlaps itself across the edges: there a pixel has two preimages
  // under map 4, and the following symbols decide which address is the top one.
  Ifs f = square_grid(2);
  f.name = "quadrants-and-diamond";
  const double k = 0.85 / std::sqrt(2.0);
  f.maps.push_back({k, -k, k, k, 0.5, 0.1});
  SuperIfs s;
  s.ifs = {f};
  s.view = kUnit;
  const cv::Size size{96, 96};
  // Some pixels do have two preimages under map 4.
  const AffineMap inverse = *f.maps[4].inverse();
  int twice = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c) {
      int preimages = 0;
      for (int i = -2; i <= 2; ++i)
        for (int j = -2; j <= 2; ++j) {
          const Point y = inverse({(c + 0.5) / size.width + i, 1 - (r + 0.5) / size.height + j});
          preimages += y.x >= 0 && y.y >= 0 && y.x < 1 && y.y < 1;
        }
      twice += preimages == 2;
    }
  EXPECT_GT(twice, 100);
  Buffers buffers(s, size, {.count = 1, .sampling = {.seamless = true}, .history = 40});
  buffers.run(40);
  const Ifs g = colouring_ifs(s, 0);
  const StealMap mine = steal_map(buffers, 0);
  const StealMap core =
      compute_steal_map(f, g, size, {.sampling = {.view = kUnit, .seamless = true}});
  for (const auto& [name, map] : {std::pair{"superIFS", &mine}, std::pair{"IFS core", &core}}) {
    EXPECT_EQ(cv::countNonZero(map->coverage), size.area()) << name;
    EXPECT_GE(distance(*map, f, g, 1e-4).close, 0.99) << name;
  }
}

TEST(seamless_texture, identity_superifs_on_the_torus_returns_the_source) {
  SuperIfs s;
  s.ifs = {square_grid(2), square_grid(2)};
  s.colouring = s.ifs;
  s.view = kUnit;
  const cv::Size size{128, 96};
  Buffers k(s, size, {.count = 3, .sampling = {.seed = 4, .seamless = true}, .history = 10});
  k.run(12);
  const StealMap map = steal_map(k, 1);
  ASSERT_EQ(cv::countNonZero(map.coverage), size.area());
  cv::Mat source(size, CV_8UC3);
  cv::randu(source, 0, 256);
  EXPECT_EQ(cv::norm(apply(map, source), source, cv::NORM_INF), 0);
}

TEST(seamless_texture, every_mode_gives_the_same_bytes_for_any_thread_count) {
  const SuperIfs s = load_superifs("carpet-lace").super;
  cv::Mat source(cv::Size(90, 70), CV_8UC3);
  cv::randu(source, 0, 256);
  for (TextureMode mode :
       {TextureMode::attractor, TextureMode::tops, TextureMode::steal, TextureMode::measure}) {
    TextureOptions o{.sampling = {.margin = 0, .seed = 3, .threads = 1, .seamless = true},
                     .mode = mode,
                     .source = source};
    const cv::Mat one = render_texture(s, {120, 96}, o);
    o.sampling.threads = 3;
    EXPECT_TRUE(testing::same_bytes(one, render_texture(s, {120, 96}, o))) << to_string(mode);
  }
}

// The shipped superIFS presets offered as seamless tiles, as `ifsfx texture --seamless` renders
// them (the preset's tile and offset), in every mode, stealing from a photograph: the seam
// statistic at most 1.15.
TEST(seamless_texture, shipped_presets_offered_as_seamless_tiles_have_no_seam) {
  const cv::Size size{192, 192};
  const cv::Mat photo = read_image("/usr/share/doc/opencv-doc/examples/data/baboon.jpg").pixels;
  int offered = 0;
  for (const SuperIfsSummary& summary : list_shipped_superifs()) {
    if (!summary.seamless) continue;
    ++offered;
    const SuperIfsPreset preset = load_superifs(summary.name);

    const TileLayout layout{.offset = preset.seamless->offset};
    for (TextureMode mode :
         {TextureMode::attractor, TextureMode::tops, TextureMode::steal, TextureMode::measure}) {
      const cv::Mat tile = render_texture(
          preset.super, size,
          {.sampling = {.view = preset.seamless->view, .margin = 0, .seamless = true},
           .mode = mode,
           .source = photo});
      const testing::SeamStatistic seam = testing::seam_statistic(tile_picture(tile, layout));
      EXPECT_LE(seam.ratio(), 1.15)
          << summary.name << ", " << to_string(mode) << ": across the edges " << seam.across_edges
          << ", inside " << seam.inside;
    }
  }
  EXPECT_GE(offered, 3);
}

}  // namespace
}  // namespace ifsfx
