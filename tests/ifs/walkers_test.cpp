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
#endif

}  // namespace
}  // namespace ifsfx::detail
