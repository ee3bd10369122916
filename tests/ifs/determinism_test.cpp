// SPDX-License-Identifier: Apache-2.0
// Same seed ⇒ same bytes, whatever the thread count (docs/style.md rule 5), in every render mode:
// attractor, measure, tops and steal maps, by the chaos game and exactly. IFSs of 2 to 9 maps,
// sizes and qualities whose point budgets span several chunks of the chaos game (so that with
// 2 or 3 threads a worker runs more than one chunk, and state a worker carries from one chunk to
// the next shows), several seeds, and 1, 2, 3 and 5 threads.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ifs/detail/walkers.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "ifs/tops.h"
#include "known_ifs.h"
#include "same_bytes.h"

namespace ifsfx {
namespace {

struct Case {
  std::string name;
  Ifs ifs;
  cv::Size size;
  std::uint64_t seed;
  double quality;  // points per pixel
};

std::vector<Case> cases() {
  const auto preset = [](const char* name) {
    return load_ifs(name, {.allow_expansive = true}).ifs;
  };
  return {
      {"twin-dragon (2 maps)", preset("twin-dragon"), {256, 192}, 7, 200},
      {"sierpinski-triangle (3 maps)", preset("sierpinski-triangle"), {301, 157}, 3, 250},
      {"barnsley-fern (4 maps)", preset("barnsley-fern"), {320, 240}, 7, 160},
      {"maple-leaf (4 maps)", preset("maple-leaf"), {200, 200}, 11, 250},
      {"koch3 (5 maps)", preset("koch3"), {240, 180}, 5, 250},
      {"sierpinski-carpet (8 maps)", testing::sierpinski_carpet(), {162, 162}, 2, 400},
      {"square-tiling-9 (9 maps)", preset("square-tiling-9"), {150, 150}, 4, 500},
  };
}

// Renders each case with 1 thread, then with 2, 3 and 5, and expects the same bytes.
template <class Render>
void expect_same_bytes_for_any_thread_count(Render render) {
  for (const Case& c : cases()) {
    const double points = c.quality * c.size.area();
    ASSERT_GT(points, 2.0 * detail::kChunkPoints) << c.name << ": a case must span 3 chunks";
    const cv::Mat one = render(c, 1);
    ASSERT_FALSE(one.empty()) << c.name;
    for (int threads : {2, 3, 5})
      EXPECT_TRUE(testing::same_bytes(one, render(c, threads)))
          << c.name << ", seed " << c.seed << ": 1 thread vs " << threads;
  }
}

cv::Mat steal_map_bytes(const StealMap& map) {
  cv::Mat out;
  cv::Mat coverage;
  map.coverage.convertTo(coverage, CV_32F);
  cv::merge(std::vector<cv::Mat>{map.source_uv, coverage}, out);
  return out;
}

TEST(determinism, attractor_does_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    return render_attractor(
        c.ifs, c.size, {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads}});
  });
}

TEST(determinism, measure_does_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    // Every other case supersampled: the same points on a finer raster.
    return render_measure(c.ifs, c.size,
                          {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads},
                           .supersample = c.seed % 2 == 0 ? 2 : 1});
  });
}

TEST(determinism, chaos_game_tops_do_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    return render_tops(c.ifs, c.size,
                       {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads},
                        .exact = false,
                        .second_symbol = true});
  });
}

TEST(determinism, exact_tops_do_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    return render_tops(c.ifs, c.size,
                       {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads},
                        .exact = true,
                        .second_symbol = true});
  });
}

TEST(determinism, chaos_game_steal_map_does_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    return steal_map_bytes(compute_steal_map(
        c.ifs, default_colouring(c.ifs.size()), c.size,
        {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads}, .exact = false}));
  });
}

TEST(determinism, exact_steal_map_does_not_depend_on_the_thread_count) {
  expect_same_bytes_for_any_thread_count([](const Case& c, int threads) {
    return steal_map_bytes(compute_steal_map(
        c.ifs, default_colouring(c.ifs.size()), c.size,
        {.sampling = {.quality = c.quality, .seed = c.seed, .threads = threads}, .exact = true}));
  });
}

}  // namespace
}  // namespace ifsfx
