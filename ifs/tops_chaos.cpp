// Fractal tops by the chaos game with a 64-bit address key per walker (DESIGN.md §2, paper eq. 7).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "ifs/chaos_game.h"
#include "ifs/detail/address_raster.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::detail {

int symbol_bits(std::size_t n) {
  return std::max(1, static_cast<int>(std::bit_width(std::max<std::size_t>(n, 2) - 1)));
}

cv::Mat AddressRaster::coverage() const {
  cv::Mat out(viewport.size, CV_8UC1);
  for (int r = 0; r < out.rows; ++r) {
    auto* row = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < out.cols; ++c) row[c] = at(c, r) != 0 ? 255 : 0;
  }
  return out;
}

namespace {

// Points per chunk: the split of the work depends only on the point count.
constexpr std::uint64_t kChunkPoints = std::uint64_t{1} << 21;
constexpr int kHutchinsonPasses = 4;
// Walkers iterated in lockstep per chunk: independent chains whose cache misses on the pixel
// buffer overlap (one walker alone waits on every store).
constexpr int kLanes = 8;

struct Kernel {
  std::vector<double> a, b, c, d, e, f;
  MapPicker pick;
  int bits = 1;
  int burn_in = 64;
  double sx = 1, ox = 0, sy = 1, oy = 0;  // plane → continuous pixel coordinates
  int width = 0, height = 0;

  Kernel(const Ifs& F, const Viewport& vp)
      : pick(effective_probabilities(F)), bits(symbol_bits(F.size())) {
    for (const auto& m : F.maps) {
      a.push_back(m.a), b.push_back(m.b), c.push_back(m.c);
      d.push_back(m.d), e.push_back(m.e), f.push_back(m.f);
    }
    // Keys are compared only once full: 64/b symbols in, on top of the usual burn-in.
    burn_in = std::max(default_burn_in(F), 64 / bits + 1);
    const AffineMap p = vp.plane_to_pixel();
    sx = p.a, ox = p.e, sy = p.d, oy = p.f;
    width = vp.size.width;
    height = vp.size.height;
  }
};

// Runs `points` chaos-game points of one chunk into `buffer`. With keys, each pixel keeps the
// largest key (Top keeps the larger address, eq. 7); without, it is marked hit.
template <bool kKeys, class Cell>
void run_chunk(const Kernel& k, std::uint64_t seed, std::uint64_t points, Cell* buffer) {
  Rng rng(seed);
  std::array<double, kLanes> x{}, y{};
  std::array<std::uint64_t, kLanes> key{};
  for (int lane = 0; lane < kLanes; ++lane) x[lane] = rng.uniform(), y[lane] = rng.uniform();
  const double *a = k.a.data(), *b = k.b.data(), *c = k.c.data();
  const double *d = k.d.data(), *e = k.e.data(), *f = k.f.data();
  const int shift = 64 - k.bits, bits = k.bits;
  for (int step = 0; step < k.burn_in; ++step)
    for (int lane = 0; lane < kLanes; ++lane) {
      const std::uint32_t n = k.pick(rng.next());
      const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
      y[lane] = c[n] * x[lane] + d[n] * y[lane] + f[n];
      x[lane] = nx;
      key[lane] = (key[lane] >> bits) | (std::uint64_t{n} << shift);
    }
  const double sx = k.sx, ox = k.ox, sy = k.sy, oy = k.oy;
  const double w = k.width, h = k.height;
  const std::size_t stride = static_cast<std::size_t>(k.width);
  auto step_lane = [&](int lane) {
    const std::uint32_t n = k.pick(rng.next());
    const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
    const double ny = c[n] * x[lane] + d[n] * y[lane] + f[n];
    x[lane] = nx;
    y[lane] = ny;
    const double px = nx * sx + ox, py = ny * sy + oy;
    if constexpr (kKeys) key[lane] = (key[lane] >> bits) | (std::uint64_t{n} << shift);
    if (px >= 0 && px < w && py >= 0 && py < h) {
      Cell& cell = buffer[static_cast<std::size_t>(py) * stride + static_cast<std::size_t>(px)];
      if constexpr (kKeys)
        cell = std::max<Cell>(cell, key[lane] | 1);
      else
        cell = 1;
    }
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t s = 0; s < steps; ++s)
    for (int lane = 0; lane < kLanes; ++lane) step_lane(lane);
  for (int lane = 0; lane < static_cast<int>(points % kLanes); ++lane) step_lane(lane);
}

// Holes: unhit pixels with hit neighbours on both sides along some line through them; they take
// the largest neighbouring record. Reads `in`, writes `out` (a copy of `in`), so the result does
// not depend on the scan order.
template <class Cell>
std::size_t fill_holes(const std::vector<Cell>& in, std::vector<Cell>& out, int width, int height) {
  std::size_t filled = 0;
  auto get = [&](int c, int r) -> Cell {
    if (c < 0 || r < 0 || c >= width || r >= height) return 0;
    return in[static_cast<std::size_t>(r) * width + c];
  };
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      if (get(c, r) != 0) continue;
      const bool inside = (get(c - 1, r) && get(c + 1, r)) || (get(c, r - 1) && get(c, r + 1)) ||
                          (get(c - 1, r - 1) && get(c + 1, r + 1)) ||
                          (get(c - 1, r + 1) && get(c + 1, r - 1));
      if (!inside) continue;
      Cell best = 0;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) best = std::max(best, get(c + dc, r + dr));
      out[static_cast<std::size_t>(r) * width + c] = best;
      ++filled;
    }
  return filled;
}

// The point a key stands for: x = f_σ1 ∘ … ∘ f_σK(c), c the fixed point of f_σK, within s^K of
// the point that carried the key; in continuous pixel coordinates.
Point point_of_key(const Ifs& F, const Kernel& k, std::uint64_t key) {
  const int symbols = 64 / k.bits;
  const auto n = static_cast<std::uint32_t>(F.size());
  auto symbol = [&](int i) {
    return std::min(
        n - 1, static_cast<std::uint32_t>((key >> (64 - k.bits * (i + 1))) & ((1u << k.bits) - 1)));
  };
  Point x = fixed_point(F.maps[symbol(symbols - 1)]);
  for (int i = symbols - 1; i >= 0; --i) x = F.maps[symbol(i)](x);
  return {x.x * k.sx + k.ox, x.y * k.sy + k.oy};
}

// Hutchinson passes: one more chaos-game step from the point of every pixel, for all maps at
// once (W(A) = A, so f_n of a point of A is a point of A with address n·σ). A pixel that no
// point reached takes the largest key among those arriving; the pixels so reached are the
// sources of the next pass. This reaches the parts of A the invariant measure barely visits
// (corners of overlapping IFSs, thin tips of the fern) without leaving A. Returns the pixels
// reached.
std::size_t hutchinson_passes(const Ifs& F, const Kernel& k, std::vector<std::uint64_t>& keys,
                              int passes) {
  const auto width = static_cast<std::size_t>(k.width);
  std::vector<std::pair<std::size_t, Point>> sources;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i] != 0) sources.emplace_back(i, point_of_key(F, k, keys[i]));
  std::size_t reached = 0;
  const int shift = 64 - k.bits;
  // The plane maps seen in pixel coordinates: P ∘ f_n ∘ P⁻¹.
  const AffineMap to_pixel{k.sx, 0, 0, k.sy, k.ox, k.oy};
  const AffineMap from_pixel = *to_pixel.inverse(0);
  std::vector<AffineMap> maps;
  for (const auto& f : F.maps) maps.push_back(to_pixel.compose(f).compose(from_pixel));
  for (int pass = 0; pass < passes && !sources.empty(); ++pass) {
    std::vector<std::pair<std::size_t, Point>> arrivals;  // (pixel, point), with its key below
    std::vector<std::uint64_t> arrival_keys;
    for (const auto& [index, x] : sources)
      for (std::size_t n = 0; n < maps.size(); ++n) {
        const Point y = maps[n](x);
        if (!(y.x >= 0 && y.x < k.width && y.y >= 0 && y.y < k.height)) continue;
        const std::size_t q = static_cast<std::size_t>(y.y) * width + static_cast<std::size_t>(y.x);
        if (keys[q] != 0) continue;
        arrivals.emplace_back(q, y);
        arrival_keys.push_back((keys[index] >> k.bits) | (std::uint64_t{n} << shift) | 1);
      }
    // Largest key per pixel (ties: equal keys, any of them).
    std::vector<std::size_t> order(arrivals.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return arrivals[a].first != arrivals[b].first ? arrivals[a].first < arrivals[b].first
                                                    : arrival_keys[a] > arrival_keys[b];
    });
    sources.clear();
    for (std::size_t i = 0; i < order.size(); ++i) {
      const std::size_t q = arrivals[order[i]].first;
      if (i > 0 && arrivals[order[i - 1]].first == q) continue;
      keys[q] = arrival_keys[order[i]];
      sources.push_back(arrivals[order[i]]);
    }
    reached += sources.size();
  }
  return reached;
}

// The coverage policy of ChaosTopsOptions over one record type; returns the merged buffer.
template <bool kKeys, class Cell>
std::vector<Cell> run_policy(const Ifs& F, const Viewport& viewport,
                             const ChaosTopsOptions& options, ChaosTopsStats* stats) {
  const Kernel kernel(F, viewport);
  const std::size_t pixels = static_cast<std::size_t>(viewport.size.area());
  const int threads = resolve_threads(options.threads);
  std::vector<std::vector<Cell>> buffers(static_cast<std::size_t>(threads));
  std::vector<Cell>& merged = buffers[0];
  merged.assign(pixels, 0);
  ChaosTopsStats s;
  std::uint64_t next_chunk = 0;
  std::size_t hit = 0;
  for (int round = 0; round <= kMaxGrowthRounds; ++round) {
    const double per_pixel = round == 0 ? options.quality : options.quality / 4;
    const auto points = static_cast<std::uint64_t>(
        std::max(1.0, std::ceil(per_pixel * static_cast<double>(pixels))));
    const std::uint64_t chunks = (points + kChunkPoints - 1) / kChunkPoints;
    const std::uint64_t first = next_chunk;
    next_chunk += chunks;
    parallel_for(chunks, threads, [&](std::size_t chunk, int worker) {
      auto& buffer = buffers[static_cast<std::size_t>(worker)];
      if (buffer.empty()) buffer.assign(pixels, 0);
      const std::uint64_t begin = chunk * kChunkPoints;
      run_chunk<kKeys>(kernel, stream_seed(options.seed, first + chunk),
                       std::min(kChunkPoints, points - begin), buffer.data());
    });
    s.points += points;
    s.rounds = round + 1;
    // Merge by max: associative and commutative, so the result is the same for any split of
    // chunks over workers (equal keys are equal records: no tie to break).
    const std::size_t rows = static_cast<std::size_t>(viewport.size.height);
    parallel_for(rows, threads, [&](std::size_t r, int) {
      Cell* out = merged.data() + r * static_cast<std::size_t>(viewport.size.width);
      for (std::size_t w = 1; w < buffers.size(); ++w) {
        if (buffers[w].empty()) continue;
        const Cell* in = buffers[w].data() + r * static_cast<std::size_t>(viewport.size.width);
        for (int c = 0; c < viewport.size.width; ++c) out[c] = std::max(out[c], in[c]);
      }
    });
    const std::size_t now =
        pixels - static_cast<std::size_t>(std::count(merged.begin(), merged.end(), Cell{0}));
    const std::size_t gained = now - hit;
    hit = now;
    if (!options.grow ||
        (round > 0 && static_cast<double>(gained) <= 1e-3 * static_cast<double>(hit)))
      break;
    if (round == 0 && gained == 0) break;  // nothing in view at all
  }
  s.hit = hit;
  if constexpr (kKeys)
    if (options.fill) s.propagated = hutchinson_passes(F, kernel, merged, kHutchinsonPasses);
  std::vector<Cell> result = merged;
  if (options.fill)
    s.filled = fill_holes(merged, result, viewport.size.width, viewport.size.height);
  if (stats) *stats = s;
  return result;
}

}  // namespace

AddressRaster chaos_tops(const Ifs& F, const Viewport& viewport, const ChaosTopsOptions& options,
                         ChaosTopsStats* stats) {
  AddressRaster out;
  out.viewport = viewport;
  out.bits = symbol_bits(F.size());
  out.keys = run_policy<true, std::uint64_t>(F, viewport, options, stats);
  return out;
}

}  // namespace ifsfx::detail
