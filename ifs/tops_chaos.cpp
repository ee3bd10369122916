// SPDX-License-Identifier: Apache-2.0
// Fractal tops by the chaos game with a 64-bit address key per walker (paper eq. 7;
// docs/design.md §2).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>

#include "ifs/chaos_game.h"
#include "ifs/detail/address_raster.h"
#include "ifs/detail/walkers.h"
#include "ifs/error.h"
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

constexpr int kHutchinsonPasses = 4;

// One map of F seen in continuous pixel coordinates, P ∘ f ∘ P⁻¹, for the Hutchinson passes, which
// step points of the pixel grid.
struct PixelMap {
  double a, b, c, d, e, f;
};

struct Kernel {
  std::vector<PixelMap> maps;
  int bits = 1;
  int width = 0, height = 0;
  AffineMap to_pixel;

  Kernel(const Ifs& F, const Viewport& vp) : bits(symbol_bits(F.size())) {
    to_pixel = vp.plane_to_pixel();
    const AffineMap from_pixel = *to_pixel.inverse(0);
    for (const auto& m : F.maps) {
      const AffineMap h = to_pixel.compose(m).compose(from_pixel);
      maps.push_back({h.a, h.b, h.c, h.d, h.e, h.f});
    }
    width = vp.size.width;
    height = vp.size.height;
  }
};

// The walkers of render.cpp with address keys (walk_kernels.h), in plane coordinates, plotted by
// the viewport's pixel mapping. Keys are compared only once full: 64/b symbols in, on top of the
// usual burn-in.
struct Walkers {
  WalkTables tables;
  const WalkKernels& kernels;

  Walkers(const Ifs& F, const Viewport& vp)
      : tables(F, vp, std::max(default_burn_in(F), 64 / symbol_bits(F.size()) + 1),
               symbol_bits(F.size())),
        kernels(walk_kernels()) {}
};

// Runs `points` chaos-game points of chunk `chunk` into `buffer`: each pixel keeps the largest
// key (Top keeps the larger address, eq. 7), cut to the top bits of a Cell (32 bits halve the
// buffer's memory traffic; they hold 32/b symbols).
template <class Cell>
void run_chunk(const KeyWalk& w, std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
               Cell* buffer) {
  if constexpr (sizeof(Cell) == 4)
    w.run32(seed, chunk, points, buffer);
  else
    w.run64(seed, chunk, points, buffer);
}

// Holes: unhit pixels with hit neighbours on both sides along some line through them (or, at a
// corner of the raster, all three neighbours hit); they take the largest neighbouring record. Reads
// `in`, writes `out` (a copy of `in`), so the result does not depend on the scan order. On the
// torus (`wrap`) the raster has no border: a pixel's neighbours across the tile's edge are the
// pixels of the opposite edge.
template <class Cell>
std::size_t fill_holes(const std::vector<Cell>& in, std::vector<Cell>& out, int width, int height,
                       bool wrap, const CancelToken& cancel) {
  std::size_t filled = 0;
  auto get = [&](int c, int r) -> Cell {
    if (wrap) {
      c = (c + width) % width;
      r = (r + height) % height;
    }
    if (c < 0 || r < 0 || c >= width || r >= height) return 0;
    return in[static_cast<std::size_t>(r) * width + c];
  };
  for (int r = 0; r < height; ++r) {
    if (r % 256 == 0) cancel.check("chaos game");
    for (int c = 0; c < width; ++c) {
      if (get(c, r) != 0) continue;
      // A corner of the raster has no line through it with both ends inside: there, its three
      // neighbours all hit say the same (an attractor running off the corner of the view).
      const bool corner = !wrap && (c == 0 || c == width - 1) && (r == 0 || r == height - 1);
      const int dc = c == 0 ? 1 : -1, dr = r == 0 ? 1 : -1;
      const bool inside = (get(c - 1, r) && get(c + 1, r)) || (get(c, r - 1) && get(c, r + 1)) ||
                          (get(c - 1, r - 1) && get(c + 1, r + 1)) ||
                          (get(c - 1, r + 1) && get(c + 1, r - 1)) ||
                          (corner && width > 1 && height > 1 && get(c + dc, r) && get(c, r + dr) &&
                           get(c + dc, r + dr));
      if (!inside) continue;
      Cell best = 0;
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) best = std::max(best, get(c + j, r + i));
      out[static_cast<std::size_t>(r) * width + c] = best;
      ++filled;
    }
  }
  return filled;
}

// A point on the pixel grid with a bound on its distance from the attractor point it stands for.
struct Located {
  std::size_t pixel;
  Point p;
  double error;  // pixels
};

// Hutchinson passes: one more chaos-game step from the point of every pixel, for all maps at
// once (W(A) = A, so f_n of a point of A is a point of A with address n·σ). A pixel's point is
// recovered from its key, x = f_σ1 ∘ … ∘ f_σK(c) with c in A, so it is known to within
// diam(A)·‖f_σ1‖⋯‖f_σK‖; only points known to kMaxError pixels take part, so that the passes
// never leave A by rounding. A pixel that no point reached takes the largest key among those
// arriving; the pixels so reached are the sources of the next pass. This reaches the parts of A
// the invariant measure barely visits (corners of overlapping IFSs) without leaving A. Returns
// the pixels reached.
std::size_t hutchinson_passes(const Ifs& F, const Kernel& k, std::vector<std::uint64_t>& keys,
                              int key_bits, int passes, const CancelToken& cancel) {
  constexpr double kMaxError = 0.05;
  const int symbols = key_bits / k.bits;
  const auto n_maps = static_cast<std::uint32_t>(F.size());
  // Keys keep their top key_bits bits (and the presence bit 0).
  const std::uint64_t kept = key_bits == 64 ? ~std::uint64_t{0} : ~(~std::uint64_t{0} >> key_bits);
  const auto width = static_cast<std::size_t>(k.width);
  const int shift = 64 - k.bits;
  std::vector<AffineMap> maps;
  std::vector<double> factor;
  for (std::size_t n = 0; n < F.size(); ++n) {
    const auto& m = k.maps[n];
    maps.push_back({m.a, m.b, m.c, m.d, m.e, m.f});
    factor.push_back(std::min(1.0, maps.back().contraction()));
  }
  const Box box = attractor_bounds(F);
  const Point c0 = k.to_pixel({box.x0, box.y0}), c1 = k.to_pixel({box.x1, box.y1});
  const double diameter = std::hypot(c1.x - c0.x, c1.y - c0.y);

  // Polled every kPoll pixels or points: these loops run over the whole raster.
  constexpr std::size_t kPoll = std::size_t{1} << 16;
  std::vector<Located> sources;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i % kPoll == 0) cancel.check("chaos game");
    if (keys[i] == 0) continue;
    auto symbol = [&](int j) {
      return std::min(n_maps - 1, static_cast<std::uint32_t>((keys[i] >> (64 - k.bits * (j + 1))) &
                                                             ((1u << k.bits) - 1)));
    };
    double error = diameter;
    for (int j = 0; j < symbols && error > kMaxError; ++j) error *= factor[symbol(j)];
    if (error > kMaxError) continue;
    Point x = k.to_pixel(fixed_point(F.maps[symbol(symbols - 1)]));
    for (int j = symbols - 1; j >= 0; --j) x = maps[symbol(j)](x);
    sources.push_back({i, x, error});
  }
  std::size_t reached = 0;
  for (int pass = 0; pass < passes && !sources.empty(); ++pass) {
    cancel.check("chaos game");
    std::vector<Located> arrivals;
    std::vector<std::uint64_t> arrival_keys;
    for (std::size_t i = 0; i < sources.size(); ++i) {
      if (i % kPoll == 0) cancel.check("chaos game");
      const Located& s = sources[i];
      for (std::uint32_t n = 0; n < n_maps; ++n) {
        const Point y = maps[n](s.p);
        if (!(y.x >= 0 && y.x < k.width && y.y >= 0 && y.y < k.height)) continue;
        const std::size_t q = static_cast<std::size_t>(y.y) * width + static_cast<std::size_t>(y.x);
        if (keys[q] != 0) continue;
        arrivals.push_back({q, y, s.error * factor[n]});
        arrival_keys.push_back((((keys[s.pixel] >> k.bits) | (std::uint64_t{n} << shift)) & kept) |
                               1);
      }
    }
    // The largest key per pixel; equal keys ordered by their points, so that the result does
    // not depend on anything but the input.
    std::vector<std::size_t> order(arrivals.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const Located &la = arrivals[a], &lb = arrivals[b];
      if (la.pixel != lb.pixel) return la.pixel < lb.pixel;
      if (arrival_keys[a] != arrival_keys[b]) return arrival_keys[a] > arrival_keys[b];
      return la.p.x != lb.p.x ? la.p.x < lb.p.x : la.p.y < lb.p.y;
    });
    sources.clear();
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Located& l = arrivals[order[i]];
      if (i > 0 && arrivals[order[i - 1]].pixel == l.pixel) continue;
      keys[l.pixel] = arrival_keys[order[i]];
      sources.push_back(l);
    }
    reached += sources.size();
  }
  return reached;
}

// The coverage policy of ChaosTopsOptions with Cell-sized records; returns 64-bit keys (the
// Cell's bits on top).
template <class Cell>
std::vector<std::uint64_t> run_policy(const KeyWalk& walkers, const Viewport& viewport,
                                      const ChaosTopsOptions& options, ChaosTopsStats* stats) {
  constexpr int kCellBits = 8 * static_cast<int>(sizeof(Cell));
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
    const std::uint64_t chunks = chunk_count(points, walkers.chunk_points);
    const std::uint64_t first = next_chunk;
    next_chunk += chunks;
    parallel_for(chunks, threads, [&](std::size_t chunk, int worker) {
      options.cancel.check("chaos game");
      auto& buffer = buffers[static_cast<std::size_t>(worker)];
      if (buffer.empty()) buffer.assign(pixels, 0);
      run_chunk<Cell>(walkers, options.seed, first + chunk,
                      chunk_size(points, chunk, walkers.chunk_points), buffer.data());
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
  std::vector<std::uint64_t> keys(pixels);
  for (std::size_t i = 0; i < pixels; ++i)
    keys[i] = merged[i] == 0 ? 0 : (std::uint64_t{merged[i]} << (64 - kCellBits)) | 1;
  buffers.clear();
  // Not on the torus: there a pixel's point, rebuilt from its key by the maps and the wraps between
  // them, is not known to within the contraction of its address (a wrap is not continuous), so the
  // passes could leave the attractor.
  if (options.fill && !viewport.wrap && walkers.affine)
    s.propagated = hutchinson_passes(*walkers.affine, Kernel(*walkers.affine, viewport), keys,
                                     kCellBits, kHutchinsonPasses, options.cancel);
  options.cancel.check("chaos game");
  std::vector<std::uint64_t> result = keys;
  if (options.fill)
    s.filled = fill_holes(keys, result, viewport.size.width, viewport.size.height, viewport.wrap,
                          options.cancel);
  if (stats) *stats = s;
  return result;
}

}  // namespace

AddressRaster chaos_tops(const KeyWalk& walk, const Viewport& viewport,
                         const ChaosTopsOptions& options, ChaosTopsStats* stats) {
  AddressRaster out;
  out.viewport = viewport;
  out.bits = walk.bits;
  out.key_bits = options.key_bits == 32 ? 32 : 64;
  out.keys = out.key_bits == 32 ? run_policy<std::uint32_t>(walk, viewport, options, stats)
                                : run_policy<std::uint64_t>(walk, viewport, options, stats);
  return out;
}

AddressRaster chaos_tops(const Ifs& F, const Viewport& viewport, const ChaosTopsOptions& options,
                         ChaosTopsStats* stats) {
  const auto walkers = std::make_shared<const Walkers>(F, viewport);
  const KeyWalk walk{
      .run32 =
          [walkers](std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                    std::uint32_t* cells) {
            walkers->kernels.tops32(walkers->tables.spec(), lane_seeds(seed, chunk), points, cells);
          },
      .run64 =
          [walkers](std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                    std::uint64_t* cells) {
            walkers->kernels.tops64(walkers->tables.spec(), lane_seeds(seed, chunk), points, cells);
          },
      .bits = symbol_bits(F.size()),
      .affine = &F};
  return chaos_tops(walk, viewport, options, stats);
}

}  // namespace ifsfx::detail
