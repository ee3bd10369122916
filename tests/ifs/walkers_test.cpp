// The AVX2 chaos-game loop against its plain scalar reference: the same chunk must plot the same
// points, in the same order, with the same maps.
#include "ifs/detail/walkers.h"

#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "known_ifs.h"

namespace ifsfx::detail {
namespace {

using Plotted = std::vector<std::tuple<int, long, std::uint32_t>>;

template <class Kernel>
Plotted run(Kernel kernel, const Ifs& ifs, const PixelMapping& mapping, std::uint64_t points) {
  const MapTable maps(ifs);
  const MapPicker pick(effective_probabilities(ifs));
  Plotted out;
  kernel(maps, pick, mapping, 42, 3, points, 20,
         [&](int lane, long pixel, std::uint32_t map) { out.emplace_back(lane, pixel, map); });
  return out;
}

#ifdef __AVX2__
TEST(walkers, avx2_loop_plots_exactly_what_the_scalar_loop_plots) {
  // Views that cut through the attractors, so that some points fall off the raster.
  const std::pair<Ifs, PixelMapping> cases[] = {
      {testing::barnsley_fern(), {64, 32, -64, 600, 97, 301, 97}},
      {testing::right_sierpinski(), {200, -50, -200, 200, 97, 301, 97}}};
  for (const auto& [ifs, mapping] : cases) {
    for (std::uint64_t points : {std::uint64_t{100'003}, std::uint64_t{1'000}}) {
      const auto scalar = run([](auto&&... a) { plot_chunk_scalar(a...); }, ifs, mapping, points);
      const auto avx2 = run([](auto&&... a) { plot_chunk_avx2(a...); }, ifs, mapping, points);
      ASSERT_GT(scalar.size(), points / 10) << ifs.name;
      EXPECT_LT(scalar.size(), points) << ifs.name << ": the view should cut the attractor";
      EXPECT_EQ(scalar, avx2) << ifs.name << ", " << points << " points";
    }
  }
}

// With keys (fractal tops): the same points, and each point's key is the maps its lane drew, most
// recent on top — checked against a key rebuilt from the maps plotted when every point lands.
TEST(walkers, keyed_avx2_loop_gives_the_keys_of_the_scalar_loop) {
  using Keyed = std::vector<std::tuple<int, long, std::uint32_t, std::uint64_t>>;
  const Ifs ifs = testing::right_sierpinski();
  const MapTable maps(ifs);
  const MapPicker pick(effective_probabilities(ifs));
  const int bits = 2;
  // The whole unit square on the raster: every point plots, so the maps of each lane are known.
  const PixelMapping all{96, 0, -96, 96.5, 97, 97, 97};
  for (const PixelMapping& mapping : {all, PixelMapping{200, -50, -200, 200, 97, 301, 97}}) {
    Keyed scalar, avx2;
    walk_chunk_scalar<true>(maps, pick, mapping, 42, 3, 10'001, 40, bits, nullptr,
                            [&](int lane, long pixel, std::uint32_t map, std::uint64_t key) {
                              scalar.emplace_back(lane, pixel, map, key);
                            });
    walk_chunk_avx2<true>(maps, pick, mapping, 42, 3, 10'001, 40, bits, nullptr,
                          [&](int lane, long pixel, std::uint32_t map, std::uint64_t key) {
                            avx2.emplace_back(lane, pixel, map, key);
                          });
    ASSERT_GT(scalar.size(), 1000u);
    EXPECT_EQ(scalar, avx2);
  }
  Keyed points;
  walk_chunk_scalar<true>(maps, pick, all, 42, 3, 8'000, 40, bits, nullptr,
                          [&](int lane, long pixel, std::uint32_t map, std::uint64_t key) {
                            points.emplace_back(lane, pixel, map, key);
                          });
  ASSERT_EQ(points.size(), 8'000u);
  std::uint64_t rebuilt[kLanes] = {};
  std::size_t checked = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& [lane, pixel, map, key] = points[i];
    EXPECT_EQ(key >> 62, map) << "point " << i << ": the map drawn is the key's first symbol";
    rebuilt[lane] = (rebuilt[lane] >> bits) | (std::uint64_t{map} << 62);
    // After 32 steps of its own, a lane's key holds only maps plotted here.
    if (i >= 32 * kLanes) {
      EXPECT_EQ(key, rebuilt[lane]) << "point " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 7000u);
}

// With palette coordinates (measure): the same points and the same c per point as the scalar loop.
TEST(walkers, coloured_avx2_loop_gives_the_palette_coordinates_of_the_scalar_loop) {
  using Coloured = std::vector<std::tuple<int, long, std::uint32_t, std::uint32_t>>;
  const Ifs ifs = testing::barnsley_fern();
  const MapTable maps(ifs);
  const MapPicker pick(effective_probabilities(ifs));
  const std::uint32_t palette[4] = {0, 21845, 43690, 65535};
  const PixelMapping mapping{64, 32, -64, 600, 97, 301, 97};
  Coloured scalar, avx2;
  walk_chunk_scalar<false, true>(maps, pick, mapping, 42, 3, 10'001, 40, 0, palette,
                                 [&](int lane, long pixel, std::uint32_t map, std::uint32_t c) {
                                   scalar.emplace_back(lane, pixel, map, c);
                                 });
  walk_chunk_avx2<false, true>(maps, pick, mapping, 42, 3, 10'001, 40, 0, palette,
                               [&](int lane, long pixel, std::uint32_t map, std::uint32_t c) {
                                 avx2.emplace_back(lane, pixel, map, c);
                               });
  ASSERT_GT(scalar.size(), 1000u);
  EXPECT_EQ(scalar, avx2);
}
#endif

}  // namespace
}  // namespace ifsfx::detail
