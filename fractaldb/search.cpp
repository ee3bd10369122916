// SPDX-License-Identifier: Apache-2.0
#include "fractaldb/search.h"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "fractaldb/render.h"
#include "ifs/detail/numpy_random.h"
#include "ifs/error.h"

namespace ifsfx::fractaldb {

namespace {

// filling_rate with the walk's buffers kept.
double filling_rate(const Category& category, int points, const std::vector<double>& draws,
                    Points& walked, WalkBuffers& buffers, std::vector<std::uint8_t>& lit) {
  // ifs_search.py: draw_point(512, 512, 6, 6, 'gray', 0), then np.count_nonzero / (512 · 512).
  const DrawSettings settings{
      .size = {512, 512}, .padding = {6, 6}, .iterations = points, .draw = DrawType::point_gray};
  walk(category, {1, 1, 1, 1, 1, 1}, settings, draws, walked, buffers);
  lit.assign(512 * 512, 0);
  std::size_t count = 0;
  for (const Pixel p : walked) {
    if (p.x >= 512 || p.y >= 512) continue;
    std::uint8_t& pixel = lit[p.y * 512u + p.x];
    count += pixel == 0;
    pixel = 1;
  }
  return static_cast<double>(count) / static_cast<double>(512 * 512);
}

}  // namespace

double filling_rate(const Category& category, int points, const std::vector<double>& draws) {
  Points walked;
  WalkBuffers buffers;
  std::vector<std::uint8_t> lit;
  return filling_rate(category, points, draws, walked, buffers, lit);
}

void search(const SearchOptions& options,
            const std::function<void(const Category& category, double rate)>& found,
            const std::function<void(const SearchProgress&)>& progress) {
  if (options.categories < 1 || options.categories > 1'000'000)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("categories: must be 1..1000000 (got {})", options.categories));
  if (!(options.rate >= 0 && options.rate <= 1))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("rate: the filling rate is a fraction in [0, 1] (got {})", options.rate));
  if (options.points < 2 || options.points > 100'000'000)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("points: must be 2..100000000 (got {})", options.points));
  // `points` points light at most that many of the 512 · 512 pixels.
  if (options.rate > options.points / (512.0 * 512.0))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("rate: {} cannot be reached with {} points (they light at most {:.4g} "
                            "of the 512x512 picture)",
                            options.rate, options.points, options.points / (512.0 * 512.0)));
  const auto start = std::chrono::steady_clock::now();
  detail::NumpyRandom random(options.seed);
  std::vector<double> draws(static_cast<std::size_t>(options.points));
  SearchProgress state{.wanted = options.categories};
  Points walked;
  WalkBuffers buffers;
  std::vector<std::uint8_t> lit;
  while (state.found < options.categories) {
    options.cancel.check("search");
    // np.random.randint(2, 8) maps, each np.random.uniform(-1.0, 1.0, 6), p ∝ |det|.
    const auto n = static_cast<std::size_t>(random.randint(2, 8));
    Category candidate;
    candidate.name = fmt::format("{:05}", state.found);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, 6> k{};
      for (double& v : k) v = random.uniform(-1.0, 1.0);
      const AffineMap f = AffineMap::from_coefficients(k);
      candidate.maps.push_back(f);
      candidate.probabilities.push_back(std::abs(f.a * f.d - f.b * f.c));
      sum += candidate.probabilities.back();
    }
    for (double& p : candidate.probabilities) p /= sum;
    for (double& r : draws) r = random.random();
    ++state.tried;
    // All maps singular (probability 0) would divide 0 by 0 in the reference: never kept.
    const double rate =
        sum > 0 ? filling_rate(candidate, options.points, draws, walked, buffers, lit) : 0;
    if (rate >= options.rate && contraction_rate(candidate.maps, candidate.probabilities) < 0) {
      found(candidate, rate);
      ++state.found;
    }
    if (progress) {
      state.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      progress(state);
    }
  }
}

std::vector<Category> search(const SearchOptions& options) {
  std::vector<Category> out;
  search(options, [&](const Category& c, double) { out.push_back(c); });
  return out;
}

}  // namespace ifsfx::fractaldb
