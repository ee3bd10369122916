// SPDX-License-Identifier: Apache-2.0
// What one evaluation of the attractor loss (collage/attractor_loss.h, issue 32) costs at the
// levels a fit cuts it at: 32², 64² and 128² at 4 chaos-game points per pixel, and the fine
// raster's 512² at 1. The target is a filled ellipse drawn 512², the maps 6 similitudes of
// ratio 0.45 on a 3 × 2 grid over it (a fit's kind of set). Per level it prints the thread's CPU
// time of the chaos game alone (the loss's raster of A: `play` and a copy), of a whole
// evaluation, and the evaluation per chaos-game point, best of 3 rounds of ~0.2 s each.
// The kernels' level is the one ifs/cpu.h picks; IFSFX_CPU=scalar|avx2 forces one.
//   build/release/bench/collage_loss_bench [N]     (N maps, default 6)
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "bench/thread_clock.h"
#include "collage/attractor_loss.h"
#include "ifs/cpu.h"

namespace {

using namespace ifsfx;

using bench::seconds_per_call;

std::vector<AffineMap> grid_maps(int count) {
  std::vector<AffineMap> maps;
  for (int k = 0; k < count; ++k) {
    const double angle = 0.4 * k, r = 0.45;
    const double x = 0.3 + 0.2 * (k % 3), y = 0.4 + 0.2 * ((k / 3) % 2);
    const double a = r * std::cos(angle), s = r * std::sin(angle);
    // Around (x, y): the map fixes the grid point, so A spreads over the ellipse.
    maps.push_back({a, -s, s, a, x - a * x + s * y, y - s * x - a * y});
  }
  return maps;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 6;
  cv::Mat target(512, 512, CV_8UC1, cv::Scalar(0));
  cv::ellipse(target, {256, 256}, {200, 140}, 20, 0, 360, cv::Scalar(255), cv::FILLED);
  const std::vector<AffineMap> maps = grid_maps(count);
  fmt::print("attractor loss, {} maps, kernels {}\n", count, to_string(cpu_level()));
  fmt::print("{:>5} {:>8} {:>11} {:>11} {:>11} {:>11}\n", "R", "points", "play ms", "eval ms",
             "play ns/pt", "eval ns/pt");
  for (const auto& [size, points] : {std::pair{32, 4.0}, {64, 4.0}, {128, 4.0}, {512, 1.0}}) {
    const collage::AttractorLoss loss(target, {.size = size, .points = points, .keep = 0});
    double sink = 0;
    const double play = seconds_per_call([&] { sink += loss.raster(maps).data[0]; });
    const double eval = seconds_per_call([&] { sink += loss(maps); });
    const double n = points * size * size;
    fmt::print("{:>5} {:>8.0f} {:>11.3f} {:>11.3f} {:>11.2f} {:>11.2f}{}\n", size, n, 1e3 * play,
               1e3 * eval, 1e9 * play / n, 1e9 * eval / n, sink < 0 ? " " : "");
  }
  return 0;
}
