// SPDX-License-Identifier: Apache-2.0
// The scalar walker and the plot sinks of every kernel level, included by each
// ifs/walk_kernels_<level>.cpp INSIDE its own namespace (ifsfx::detail::kernel_<level>), so that
// every level compiles its own copy with its own instruction set and none is shared with another
// level or with the baseline code (see walk_kernels.h). Hence no include guard, no #include, and
// no std:: function or template here: only builtin types, the plain structs of walk_kernels.h,
// and functions of this namespace.
//
// The including file defines, after this one and before walk_kernels_table.inl, its walker:
//   template <class Sink>
//   void walk(const WalkSpec&, const LaneSeeds&, std::uint64_t points, Sink& sink);
// which must plot exactly what walk_scalar below plots, in the same order.

// xoshiro256+ (Blackman and Vigna): plain 64-bit shifts, xors and adds, so that four or eight
// lanes run in one vector register and this scalar step is their bit-exact reference.
[[gnu::always_inline]] inline std::uint64_t xoshiro_next(std::uint64_t* s) {
  const std::uint64_t result = s[0] + s[3];
  const std::uint64_t t = s[1] << 17;
  s[2] ^= s[0];
  s[3] ^= s[1];
  s[1] ^= s[2];
  s[0] ^= s[3];
  s[2] ^= t;
  s[3] = (s[3] << 45) | (s[3] >> 19);
  return result;
}

// A uniform coordinate in [0, 1) from one draw (53 bits).
inline double unit_interval(std::uint64_t r) {
  return static_cast<double>(r >> 11) * 0x1.0p-53;
}

// The wrap onto the torus of the tile (WalkSpec::wrap): t − ⌊t⌋ in [0, 1). A tiny negative t
// gives 1 by rounding, which is 0 on the torus; a NaN or an infinity (a walker that diverged)
// gives 0 too, so the walker starts again from the tile's corner.
[[gnu::always_inline]] inline double wrap_unit(double t) {
  const double r = t - __builtin_floor(t);
  return r < 1.0 ? r : 0.0;
}

// Walker's alias method (MapPicker): the high 32 bits pick a column, the low 32 bits decide
// between the column and its alias.
[[gnu::always_inline]] inline std::uint32_t pick_map(const WalkSpec& w, std::uint64_t r) {
  const auto column = static_cast<std::uint32_t>(((r >> 32) * w.pick_n) >> 32);
  return static_cast<std::uint32_t>(r) < w.threshold[column] ? column : w.alias[column];
}

// Sinks: what a mode does with a point that lands on the raster. plot(lane, pixel, map, key, c,
// x, y) gets the lane's address key (when kKeys), palette coordinate (when kPalette) and the point
// in the plane (when kPoints; else 0).
struct HitSink {
  static constexpr bool kKeys = false, kPalette = false, kPoints = false, kQuads = false;
  std::uint8_t* hits;
  void plot(int, long pixel, std::uint32_t, std::uint64_t, std::uint32_t, double, double) {
    hits[pixel] = 255;
  }
};

struct CountSink {
  static constexpr bool kKeys = false, kPalette = false, kPoints = false, kQuads = false;
  std::uint32_t* counts;
  void plot(int, long pixel, std::uint32_t, std::uint64_t, std::uint32_t, double, double) {
    ++counts[pixel];
  }
};

// The cells of MeasureCells. Each point's cell is prefetched when it lands and added to kDelay
// points later, so the cache miss of its read overlaps the walk instead of stalling it (the add
// is a read-modify-write: without the delay, the walker's steps wait behind the reads). The
// order of the adds changes nothing: the totals are sums. The waiting slots start as "add 0 to
// cell 0", which changes nothing either (a stored count is below kFull, so it does not spill).
struct MeasureSink {
  static constexpr bool kKeys = false, kPalette = true, kPoints = false;
  static constexpr unsigned kDelay = 16;
  MeasureCells m;
  std::uint32_t waiting_cell[kDelay] = {};
  std::uint32_t waiting_add[kDelay] = {};
  unsigned next = 0;

  [[gnu::always_inline]] void add(std::uint32_t cell, std::uint32_t increment) {
    std::uint32_t v = m.cells[cell] + increment;
    if ((v & MeasureCells::kFull) == MeasureCells::kFull) {
      m.spills[m.spilled++] =
          static_cast<std::uint64_t>(v >> MeasureCells::kCountBits) << 32 | cell;
      v = 0;
    }
    m.cells[cell] = v;
  }
  void plot(int, long pixel, std::uint32_t, std::uint64_t, std::uint32_t c, double, double) {
    constexpr int kBits = MeasureCells::kPaletteBits;
    // c (16 bits) rounded to kBits bits, at most 2^kBits − 1.
    std::uint32_t c6 = (c + (1u << (15 - kBits))) >> (16 - kBits);
    if (c6 > (1u << kBits) - 1) c6 = (1u << kBits) - 1;
    __builtin_prefetch(m.cells + pixel, 1);
    const unsigned slot = next++ % kDelay;
    add(waiting_cell[slot], waiting_add[slot]);
    waiting_cell[slot] = static_cast<std::uint32_t>(pixel);
    waiting_add[slot] = (c6 << MeasureCells::kCountBits) | 1;
  }
  // Four points at once, their cells and increments (c6 << kCountBits | 1) computed by a vector
  // walker (walk_quads.inl); a lane off the raster comes as "add 0 to cell 0". Only for a sink
  // that plot() is not called on.
  static constexpr bool kQuads = true;
  [[gnu::always_inline]] void plot4(const std::uint32_t* cell, const std::uint32_t* increment) {
    static_assert(kDelay % 4 == 0);
    for (int j = 0; j < 4; ++j) __builtin_prefetch(m.cells + cell[j], 1);
    const unsigned slot = next % kDelay;
    next += 4;
    for (unsigned j = 0; j < 4; ++j) {
      add(waiting_cell[slot + j], waiting_add[slot + j]);
      waiting_cell[slot + j] = cell[j];
      waiting_add[slot + j] = increment[j];
    }
  }
  // Adds the points still waiting.
  void finish() {
    for (unsigned k = 0; k < kDelay; ++k) add(waiting_cell[k], waiting_add[k]);
  }
};

// Top keeps the larger address (eq. 7): each cell keeps the largest key, cut to the Cell's top
// bits, bit 0 set to mark the cell as hit.
template <class Cell>
struct TopsSink {
  static constexpr bool kKeys = true, kPalette = false, kPoints = false, kQuads = false;
  static constexpr int kShift = 64 - 8 * static_cast<int>(sizeof(Cell));
  Cell* cells;
  void plot(int, long pixel, std::uint32_t, std::uint64_t key, std::uint32_t, double, double) {
    const Cell v = static_cast<Cell>(key >> kShift) | 1;
    Cell& cell = cells[pixel];
    if (v > cell) cell = v;
  }
};

struct TraceSink {
  static constexpr bool kKeys = true, kPalette = true, kPoints = true, kQuads = false;
  TracedPoint* out;
  std::size_t count;
  void plot(int lane, long pixel, std::uint32_t map, std::uint64_t key, std::uint32_t c, double x,
            double y) {
    out[count++] = TracedPoint{lane, map, pixel, key, c, 0, x, y};
  }
};

// The reference walker: the kLanes lanes of one chunk, step by step. Each lane starts at a
// uniform point of [0,1)² drawn from its own generator, runs its burn-in, then plots every point
// that lands on the raster. With Sink::kKeys each lane keeps the address key of its point
// (ifs/detail/address_raster.h: each step shifts the key right by key_bits and puts the map drawn
// in the top bits, burn-in included); with Sink::kPalette its palette coordinate
// c_k = (c_{k−1} + c_σk) / 2 (docs/design.md §4) in 16-bit fixed point, from 0 at the chunk's
// start and updated at every step, burn-in and points off the raster included: like the position,
// it is the walker's own state, so it depends on the lane's own draws only, never on what a worker
// ran before. Everything the loop reads is copied into locals first, so that the compiler keeps it
// in registers whatever the sink writes. With kWrap (WalkSpec::wrap) every step ends with the
// wrap onto the torus of the tile, burn-in included.
template <class Sink, bool kWrap>
void walk_scalar(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  const double *a = w.a, *b = w.b, *c = w.c, *d = w.d, *e = w.e, *f = w.f;
  const double sx = w.sx, ox = w.ox, sy = w.sy, oy = w.oy;
  const double width = w.width, height = w.height;
  const long stride = w.stride;
  const int key_bits = w.key_bits, key_shift = 64 - w.key_bits;
  const std::uint32_t* palette = w.palette;
  std::uint64_t rng[kLanes][4];
  double x[kLanes], y[kLanes];
  std::uint64_t key[kLanes];
  std::uint32_t colour[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) {
    for (int k = 0; k < 4; ++k) rng[lane][k] = seeds.s[lane][k];
    x[lane] = unit_interval(xoshiro_next(rng[lane]));
    y[lane] = unit_interval(xoshiro_next(rng[lane]));
    key[lane] = 0;
    colour[lane] = 0;
  }
  auto step = [&](int lane) {
    const std::uint32_t n = pick_map(w, xoshiro_next(rng[lane]));
    // (a x + b y) + e, (c x + d y) + f: the order every kernel level keeps.
    const double nx = a[n] * x[lane] + b[n] * y[lane] + e[n];
    const double ny = c[n] * x[lane] + d[n] * y[lane] + f[n];
    if constexpr (kWrap) {
      x[lane] = wrap_unit(nx);
      y[lane] = wrap_unit(ny);
    } else {
      x[lane] = nx;
      y[lane] = ny;
    }
    if constexpr (Sink::kKeys)
      key[lane] = (key[lane] >> key_bits) | (static_cast<std::uint64_t>(n) << key_shift);
    if constexpr (Sink::kPalette) colour[lane] = (colour[lane] + palette[n]) >> 1;
    return n;
  };
  for (int k = 0; k < w.burn_in; ++k)
    for (int lane = 0; lane < kLanes; ++lane) step(lane);
  auto advance = [&](int lane) {
    const std::uint32_t n = step(lane);
    const double px = sx * x[lane] + ox, py = sy * y[lane] + oy;
    // Non-short-circuit tests: one well-predicted branch instead of four.
    if ((px >= 0) & (px < width) & (py >= 0) & (py < height))
      sink.plot(lane, static_cast<long>(py) * stride + static_cast<long>(px), n, key[lane],
                colour[lane], x[lane], y[lane]);
  };
  const std::uint64_t steps = points / kLanes;
  for (std::uint64_t k = 0; k < steps; ++k) {
#pragma GCC unroll 8
    for (int lane = 0; lane < kLanes; ++lane) advance(lane);
  }
  for (int lane = 0; lane < static_cast<int>(points % kLanes); ++lane) advance(lane);
}

// walk_scalar with the wrap chosen at run time, once per chunk.
template <class Sink>
void walk_scalar(const WalkSpec& w, const LaneSeeds& seeds, std::uint64_t points, Sink& sink) {
  if (w.wrap)
    walk_scalar<Sink, true>(w, seeds, points, sink);
  else
    walk_scalar<Sink, false>(w, seeds, points, sink);
}
