// SPDX-License-Identifier: Apache-2.0
// Every kernel level this CPU runs against the scalar level, byte for byte, in every mode (the
// points plotted with their maps, keys and palette coordinates; hits; counts; the measure cells;
// tops of 32 and 64 bits): IFSs of 2 to 9 maps, of the vector kernels' limits (8 and 16 maps) and
// beyond (17), views that cut the attractor, point counts that do not fill the last step. Levels
// this CPU lacks are skipped, saying so.
#include "ifs/detail/walk_kernels.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "ifs/cpu.h"
#include "ifs/detail/address_raster.h"
#include "ifs/detail/walkers.h"
#include "ifs/error.h"
#include "ifs/preset.h"
#include "known_ifs.h"

namespace ifsfx::detail {
namespace {

struct Case {
  std::string name;
  Ifs ifs;
};

// N maps of factor 1/2 turned a little each, towards the corners of an N-gon: any N.
Ifs polygon_ifs(int n) {
  Ifs ifs;
  ifs.name = fmt::format("{}-gon", n);
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * 3.141592653589793 * k / n, turn = 0.1 * k;
    const double s = 0.45, cs = s * std::cos(turn), sn = s * std::sin(turn);
    ifs.maps.push_back({cs, -sn, sn, cs, 0.5 * std::cos(angle), 0.5 * std::sin(angle)});
  }
  // Unequal probabilities, so the alias table has aliases.
  for (int k = 0; k < n; ++k) ifs.probabilities.push_back(1.0 + k % 3);
  return ifs;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"twin-dragon", load_ifs("twin-dragon").ifs});
  out.push_back({"sierpinski", testing::sierpinski_triangle()});
  out.push_back({"fern", testing::barnsley_fern()});
  for (int n : {5, 6, 7, 8, 9, 12, 16, 17})
    out.push_back({fmt::format("{}-gon", n), polygon_ifs(n)});
  return out;
}

// A view of the attractor's box moved and shrunk, so that some points fall off the raster.
Viewport cut_view(const Ifs& ifs) {
  const Box b = attractor_bounds(ifs);
  return {{b.x0 + 0.2 * b.width(), b.y0 - 0.1 * b.height(), b.x1 + 0.1 * b.width(),
           b.y1 - 0.25 * b.height()},
          {97, 61}};
}

// The torus of a tile inside the attractor's box (docs/design.md §11): the maps wrap.
Viewport torus_view(const Ifs& ifs) {
  const Box b = attractor_bounds(ifs);
  return {{b.x0 + 0.15 * b.width(), b.y0 + 0.1 * b.height(), b.x1 - 0.2 * b.width(),
           b.y1 - 0.05 * b.height()},
          {89, 67},
          true};
}

class WalkKernelsAtLevel : public ::testing::TestWithParam<CpuLevel> {
 protected:
  void SetUp() override {
    const auto levels = supported_cpu_levels();
    if (std::find(levels.begin(), levels.end(), GetParam()) == levels.end())
      GTEST_SKIP() << "this CPU does not run the " << to_string(GetParam())
                   << " kernels: level not tested here";
  }
  const WalkKernels& kernels() const { return walk_kernels(GetParam()); }
  static const WalkKernels& reference() { return walk_kernels(CpuLevel::scalar); }
};

constexpr std::uint64_t kPointCounts[] = {100'003, 1'000, 5};

bool operator==(const TracedPoint& a, const TracedPoint& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST_P(WalkKernelsAtLevel, plot_the_points_maps_keys_and_palette_of_the_scalar_level) {
  for (const Case& c : cases())
    for (const Viewport& view : {cut_view(c.ifs), torus_view(c.ifs)}) {
      WalkTables walk(c.ifs, view, 20, symbol_bits(c.ifs.size()));
      for (std::uint64_t points : kPointCounts) {
        std::vector<TracedPoint> mine(points), scalar(points);
        const LaneSeeds seeds = lane_seeds(42, 3);
        mine.resize(kernels().trace(walk.spec(), seeds, points, mine.data()));
        scalar.resize(reference().trace(walk.spec(), seeds, points, scalar.data()));
        if (points > 1000) {
          ASSERT_GT(scalar.size(), points / 10) << c.name;
          if (!view.wrap) {
            EXPECT_LT(scalar.size(), points) << c.name << ": the view should cut the attractor";
          } else {
            // On the torus every point lies in the tile.
            for (const TracedPoint& p : scalar)
              ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1) << c.name;
          }
        }
        ASSERT_EQ(mine.size(), scalar.size()) << c.name << ", " << points << " points";
        std::size_t first = 0;
        while (first < mine.size() && mine[first] == scalar[first]) ++first;
        EXPECT_EQ(first, mine.size()) << c.name << (view.wrap ? " on the torus" : "") << ", "
                                      << points << " points: first difference at " << first;
      }
    }
}

template <class T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST_P(WalkKernelsAtLevel, hits_counts_and_tops_are_the_scalar_ones) {
  for (const Case& c : cases())
    for (const Viewport& view : {cut_view(c.ifs), torus_view(c.ifs)}) {
      WalkTables walk(c.ifs, view, 20, symbol_bits(c.ifs.size()));
      const auto area = static_cast<std::size_t>(view.size.area());
      const std::uint64_t points = 200'007;
      const LaneSeeds seeds = lane_seeds(7, 11);
      std::vector<std::uint8_t> hits(area), hits_ref(area);
      std::vector<std::uint32_t> counts(area), counts_ref(area), tops32(area), tops32_ref(area);
      std::vector<std::uint64_t> tops64(area), tops64_ref(area);
      kernels().hits(walk.spec(), seeds, points, hits.data());
      reference().hits(walk.spec(), seeds, points, hits_ref.data());
      kernels().counts(walk.spec(), seeds, points, counts.data());
      reference().counts(walk.spec(), seeds, points, counts_ref.data());
      kernels().tops32(walk.spec(), seeds, points, tops32.data());
      reference().tops32(walk.spec(), seeds, points, tops32_ref.data());
      kernels().tops64(walk.spec(), seeds, points, tops64.data());
      reference().tops64(walk.spec(), seeds, points, tops64_ref.data());
      EXPECT_GT(std::count(hits_ref.begin(), hits_ref.end(), 255), 100) << c.name;
      EXPECT_TRUE(same(hits, hits_ref)) << c.name;
      EXPECT_TRUE(same(counts, counts_ref)) << c.name;
      EXPECT_TRUE(same(tops32, tops32_ref)) << c.name;
      EXPECT_TRUE(same(tops64, tops64_ref)) << c.name;
    }
}

// The measure cells (counts and palette sums) through the tile queues, flushed.
TEST_P(WalkKernelsAtLevel, measure_cells_are_the_scalar_ones) {
  for (const Case& c : cases())
    for (const bool wrap : {false, true}) {
      const Viewport view =
          wrap ? Viewport{torus_view(c.ifs).view, {300, 240}, true}
               : Viewport{fit_view(attractor_bounds(c.ifs), {300, 240}), {300, 240}};
      WalkTables walk(c.ifs, view, 20);
      auto run = [&](const WalkKernels& k) {
        const auto area = static_cast<std::size_t>(view.size.area());
        std::vector<std::uint32_t> cells(area);
        std::vector<std::uint64_t> spills(3 * 300'001 / MeasureCells::kFull), totals(2 * area);
        MeasureCells m{cells.data(), spills.data(), 0};
        for (std::uint64_t chunk = 0; chunk < 3; ++chunk)
          k.measure(walk.spec(), lane_seeds(5, chunk), 300'001, m);
        fold_measure_cells(m, area, totals.data(), totals.data() + area);
        return totals;
      };
      const auto totals = run(kernels()), ref = run(reference());
      std::uint64_t total = 0;
      for (std::size_t i = 0; i < ref.size() / 2; ++i) total += ref[i];
      EXPECT_GT(total, 800'000u) << c.name;
      EXPECT_TRUE(same(totals, ref)) << c.name;
    }
}

// Cells hit more than MeasureCells::kFull times spill, over several chunks: on a 3×2 raster
// every cell on the attractor does, and the folded totals must still be the visit counts and the
// sums of the points' palette coordinates rounded to 6 bits, read from the traced points.
TEST_P(WalkKernelsAtLevel, measure_cells_that_spill_keep_exact_totals) {
  const Ifs ifs = testing::sierpinski_triangle();
  const Viewport view{attractor_bounds(ifs), {3, 2}};
  const WalkTables walk(ifs, view, 20);
  const std::size_t area = 6;
  const std::uint64_t points = 150'001, chunks = 3;
  std::vector<std::uint64_t> count_ref(area), colour_ref(area);
  std::vector<TracedPoint> traced(points);
  for (std::uint64_t chunk = 0; chunk < chunks; ++chunk) {
    traced.resize(points);
    traced.resize(reference().trace(walk.spec(), lane_seeds(9, chunk), points, traced.data()));
    for (const TracedPoint& p : traced) {
      ++count_ref[static_cast<std::size_t>(p.pixel)];
      colour_ref[static_cast<std::size_t>(p.pixel)] += std::min((p.palette + 512) >> 10, 63u);
    }
  }
  std::vector<std::uint32_t> cells(area);
  std::vector<std::uint64_t> spills(chunks * points / MeasureCells::kFull);
  std::vector<std::uint64_t> count(area), colour(area);
  MeasureCells m{cells.data(), spills.data(), 0};
  for (std::uint64_t chunk = 0; chunk < chunks; ++chunk)
    kernels().measure(walk.spec(), lane_seeds(9, chunk), points, m);
  EXPECT_GT(m.spilled, 20u);
  fold_measure_cells(m, area, count.data(), colour.data());
  for (std::size_t i = 0; i < area; ++i) {
    if (count_ref[i] > 0) {
      EXPECT_GT(count_ref[i], MeasureCells::kFull) << "cell " << i;
    }
    EXPECT_EQ(count[i], count_ref[i]) << "cell " << i;
    EXPECT_EQ(colour[i], colour_ref[i]) << "cell " << i;
  }
  EXPECT_EQ(m.spilled, 0u);
  EXPECT_EQ(std::count(cells.begin(), cells.end(), 0u), 6) << "the fold empties the cells";
}

INSTANTIATE_TEST_SUITE_P(levels, WalkKernelsAtLevel,
                         ::testing::Values(CpuLevel::scalar, CpuLevel::avx2, CpuLevel::avx512),
                         [](const ::testing::TestParamInfo<CpuLevel>& level) {
                           return std::string(to_string(level.param));
                         });

// The keys: each point's key is the maps its lane drew, most recent on top — checked against keys
// rebuilt from the maps plotted, on a raster every point lands on.
TEST(walk_kernels, keys_hold_the_maps_drawn_most_recent_first) {
  const Ifs ifs = testing::right_sierpinski();
  const int bits = 2;
  WalkTables walk(ifs, {{-0.01, -0.01, 1.01, 1.01}, {97, 97}}, 40, bits);
  std::vector<TracedPoint> points(8'000);
  points.resize(
      walk_kernels(CpuLevel::scalar).trace(walk.spec(), lane_seeds(42, 3), 8'000, points.data()));
  ASSERT_EQ(points.size(), 8'000u);
  std::uint64_t rebuilt[kLanes] = {};
  std::size_t checked = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TracedPoint& p = points[i];
    EXPECT_EQ(p.key >> 62, p.map) << "point " << i << ": the map drawn is the key's first symbol";
    rebuilt[p.lane] = (rebuilt[p.lane] >> bits) | (std::uint64_t{p.map} << 62);
    // After 32 steps of its own, a lane's key holds only maps plotted here.
    if (i >= 32 * kLanes) {
      EXPECT_EQ(p.key, rebuilt[p.lane]) << "point " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 7000u);
}

// The palette coordinate c_k = (c_{k−1} + c_σk) / 2 (16-bit fixed point, from 0 at the chunk's
// start) follows the maps the lane drew: rebuilt from the maps plotted, on a raster every point
// lands on, without burn-in.
TEST(walk_kernels, palette_coordinate_is_the_running_mean_of_the_maps_drawn) {
  const Ifs ifs = testing::right_sierpinski();
  WalkTables walk(ifs, {{-0.01, -0.01, 1.01, 1.01}, {97, 97}}, 0);
  const std::uint32_t c_n[3] = {0, 32768, 65535};  // n / (N − 1) in 16 bits
  std::vector<TracedPoint> points(4'000);
  points.resize(
      walk_kernels(CpuLevel::scalar).trace(walk.spec(), lane_seeds(1, 0), 4'000, points.data()));
  ASSERT_EQ(points.size(), 4'000u);
  std::uint32_t c[kLanes] = {};
  for (const TracedPoint& p : points) {
    c[p.lane] = (c[p.lane] + c_n[p.map]) >> 1;
    EXPECT_EQ(p.palette, c[p.lane]);
  }
}

TEST(walk_kernels, a_level_this_cpu_lacks_is_refused) {
  const auto levels = supported_cpu_levels();
  if (levels.back() == CpuLevel::avx512) GTEST_SKIP() << "this CPU runs every level";
  EXPECT_THROW(walk_kernels(CpuLevel::avx512), Error);
}

}  // namespace
}  // namespace ifsfx::detail
