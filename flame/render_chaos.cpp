// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>

#include <fmt/format.h>

#include "flame/detail/batch_variations.h"
#include "flame/detail/render_chaos.h"
#include "flame/detail/xform_step.h"
#include "flame/variations.h"
#include "flame/xform_pickers.h"
#include "ifs/error.h"
#include "ifs/large_buffer.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::flame::detail {
namespace {

// flam3's sub-batch: each walker plots this many points from its own random start. Flames
// whose maps do not contract (a pure rotation draws one circle per start) show the count. A
// chunk is kBatchLanes walkers in lockstep, so that the walkers that picked one xform go through
// its variations together (flame/detail/batch_variations.h).
constexpr std::uint64_t kWalkerPoints = 10000;
constexpr std::uint64_t kChunkPoints = kWalkerPoints * kBatchLanes;
constexpr double kUnit = 65536;  // one hit of full colour, in the integer sums
constexpr std::size_t kN = kStepStride;

// Four 32-bit sums or colour channels (r, g, b, a) as one value: GCC's generic vectors, plain
// SSE2 on x86-64, scalar code elsewhere.
using U4 = std::uint32_t __attribute__((vector_size(16)));

// An xform prepared for the loop: its motion (flame/detail/xform_step.h) and the colour update
// c ← keep·c + shift.
struct Step {
  XformStep motion;
  double keep = 1, shift = 0;
  std::array<U4, 256> colours{};  // palette × opacity (r, g, b, a), in kUnit
  // Every entry 0 (opacity 0, as flames use to hide an xform's own points): its hits add
  // nothing and are not plotted at all (flam3-render skips them too).
  bool invisible = false;
};

// An affine_only step flat, for the walk's point-by-point loop: its maps, the sum's weights and
// the colour update in one small record (a Step with its colours is over 4 KB, and its terms
// are behind a pointer). The maps as PairMaps: x and y in one pair of lanes.
constexpr std::size_t kFlatTerms = 4;
struct Flat {
  PairMap pre, post;
  std::array<D2, kFlatTerms> w{};  // the sum's linear weights, in order, each in both lanes
  double keep = 1, shift = 0;
  std::uint32_t terms = 0;
  bool has_sum = false, has_post = false;
};

// The shapes that every step of a flat plan shares, so that the loop has no branch on them:
// any (the record says), or a sum of one term with a post map, or without.
enum class FlatShape { any, one_term_post, one_term };

Step step_of(const Xform& xf, const Palette& palette, Kernels kernels) {
  Step s;
  s.motion = xform_step_of(xf, kernels);
  s.keep = 1 - xf.colour_speed;
  s.shift = xf.colour_speed * xf.colour;
  for (std::size_t i = 0; i < 256; ++i) {
    const Rgba& c = palette.colours[i];
    // Clamped to [0, 1] (flame/flame.h's range), so that an entry is at most kUnit (Bins).
    const double k = std::clamp(xf.opacity, 0.0, 1.0) * std::clamp(c.a, 0.0, 1.0) * kUnit;
    // The colour channels carry the palette's alpha too: flam3 adds the entry premultiplied.
    s.colours[i] = U4{static_cast<std::uint32_t>(std::lround(c.r * k)),
                      static_cast<std::uint32_t>(std::lround(c.g * k)),
                      static_cast<std::uint32_t>(std::lround(c.b * k)),
                      static_cast<std::uint32_t>(std::lround(k))};
  }
  s.invisible = std::all_of(s.colours.begin(), s.colours.end(),
                            [](const U4& e) { return (e[0] | e[1] | e[2] | e[3]) == 0; });
  return s;
}

struct Plan {
  std::vector<Step> steps;
  std::optional<Step> final_step;
  std::vector<MapPicker> pickers;
  bool linear_palette = false;
  bool affine_only = false;  // every step affine_only: pick() moves the walkers
  std::vector<Flat> flat;    // the steps as Flat records, when affine_only with few terms
  FlatShape flat_shape = FlatShape::any;
  std::array<Rgba, 256> palette{};
  BinGrid grid;
  BinFunction bin_numbers = nullptr;          // the kernel level's
  std::vector<std::uint8_t> invisible;        // steps[k].invisible, compact for the walk's lookup
  std::vector<const std::uint32_t*> colours;  // steps[k].colours
  std::vector<std::uint32_t> fixed;           // PlotTables::fixed, when it applies
  PlotTables tables;
  PlotFunction plot = nullptr;  // the kernel level's
  HitsFunction hits = nullptr;  // the kernel level's
  ListFunction list = nullptr;  // the kernel level's, for at most kListXforms steps
  bool any_invisible = false;
};

// The histogram of one worker: r, g, b, a integer sums per bin, 32 bits each so that a bin is
// 16 bytes and twice as many stay in cache as with 64-bit sums. A sum that wraps past 2³² logs
// its index in `carries` (each entry worth 2³²): a hit adds at most kUnit = 2¹⁶, so a run of
// P points logs at most P/2¹⁶ carries, and lo + 2³²·carries is the exact 64-bit sum.
struct Bins {
  std::vector<std::uint32_t, LargeBufferAllocator<std::uint32_t>> lo;
  std::vector<std::size_t> carries;
  explicit Bins(const FlameRaster& r) : lo(4 * static_cast<std::size_t>(r.bins_x) * r.bins_y) {}
};

// Plots the points whose bin `at` is not kOffBin, listed first (HitsFunction). (A pass
// prefetching the step's 256 bins first cost more than it saved, 0-14 % of the CPU on genomes
// and Sierpinski flames, 27 Nov 17:44: the plot's own loads already overlap their misses.)
void plot_all(const Plan& plan, const std::array<std::uint32_t, kN>& at,
              const std::array<std::uint32_t, kN>& k, const std::array<double, kN>& c,
              std::size_t m, Bins& bins) {
  std::array<std::uint32_t, kN> list;
  const std::size_t n = plan.hits(at.data(), m, list.data());
  // Every walker plots (a linear flame's usual step): no indirection.
  const std::uint32_t* hits = n == m ? nullptr : list.data();
  for (std::size_t j = 0; j < n;) {
    unsigned wrapped = 0;
    j = plan.plot(plan.tables, bins.lo.data(), j, n, hits, at.data(), k.data(), c.data(), &wrapped);
    const std::size_t i = hits ? hits[j - 1] : j - 1;
    for (std::size_t ch = 0; ch < 4; ++ch)
      if ((wrapped >> ch & 1) != 0) bins.carries.push_back(4 * std::size_t{at[i]} + ch);
  }
}

// The walkers of one chunk. They stay in place; each step lists them by the xform they picked.
struct Walkers {
  std::array<double, kN> x{}, y{}, c{};
  std::array<std::uint32_t, kN> k{};      // the xform that moved it last (its picker row, colours)
  std::array<std::uint64_t, kN> limit{};  // the step at which it stops plotting
  std::uint64_t first_limit = 0;          // the smallest limit
};

// A walker's start: a random point in [−1, 1]², a random colour.
void start(Walkers& a, std::size_t i, Rng& rng) {
  a.x[i] = 2 * rng.uniform() - 1;
  a.y[i] = 2 * rng.uniform() - 1;
  a.c[i] = rng.uniform();
}

// Each walker moved by the Flat record of its xform: XformStep::moved's operations in its order
// (the sum from 0, w·q added term by term), so the same bits, with the shape's branches resolved.
template <FlatShape Shape, bool Colour>
void move_flat(const Plan& plan, Walkers& a, std::size_t m) {
  const Flat* flat = plan.flat.data();
  for (std::size_t i = 0; i < m; ++i) {
    const Flat& s = flat[a.k[i]];
    D2 p = s.pre(a.x[i], a.y[i]);
    if (Shape != FlatShape::any || s.has_sum) {
      const D2 q = p;
      const std::uint32_t terms = Shape == FlatShape::any ? s.terms : 1;
      p = D2{0, 0};
      for (std::uint32_t t = 0; t < terms; ++t) p += s.w[t] * q;
    }
    if (Shape == FlatShape::one_term_post || (Shape == FlatShape::any && s.has_post))
      p = s.post(p[0], p[1]);
    a.x[i] = p[0];
    a.y[i] = p[1];
    if (Colour) a.c[i] = s.keep * a.c[i] + s.shift;
  }
}

// The shape's move, and without the colour update where the plot reads no coordinate (each
// xform's hits one fixed colour, fix_colours: the walkers' c is then never read).
template <FlatShape Shape>
void move_flat(const Plan& plan, Walkers& a, std::size_t m) {
  if (plan.tables.fixed) return move_flat<Shape, false>(plan, a, m);
  move_flat<Shape, true>(plan, a, m);
}

// Each of the m walkers picks its next xform (a.k ← it). A plan of affine_only steps moves each
// walker by it here; otherwise order[first[j], first[j + 1]) lists the walkers that picked xform
// j (next: 4 × the xform count, scratch).
void pick(const Plan& plan, Walkers& a, std::size_t m, std::vector<std::size_t>& first,
          std::vector<std::size_t>& next, std::array<std::uint32_t, kN>& order, Rng& rng) {
  const bool xaos = plan.pickers.size() > 1;
  for (std::size_t i = 0; i < m; ++i) {
    a.k[i] = plan.pickers[xaos ? 1 + a.k[i] : 0].view().branch_free(rng.next());
  }
  if (!plan.flat.empty()) {
    switch (plan.flat_shape) {
      case FlatShape::one_term_post:
        return move_flat<FlatShape::one_term_post>(plan, a, m);
      case FlatShape::one_term:
        return move_flat<FlatShape::one_term>(plan, a, m);
      case FlatShape::any:
        return move_flat<FlatShape::any>(plan, a, m);
    }
  }
  if (plan.affine_only) {
    // The general walk's step (XformStep::operator()), point by point, with the same bits.
    for (std::size_t i = 0; i < m; ++i) {
      const Step& s = plan.steps[a.k[i]];
      const Point p = s.motion.moved(a.x[i], a.y[i]);
      a.x[i] = p.x;
      a.y[i] = p.y;
      a.c[i] = s.keep * a.c[i] + s.shift;
    }
    return;
  }
  const std::size_t steps = plan.steps.size();
  if (steps <= kListXforms) return plan.list(a.k.data(), m, steps, order.data(), first.data());
  // More xforms: a counting sort with four rows of counters, walker i on row i mod 4, so that
  // walkers of one xform in a row do not each wait for the last one's counter (a store to load
  // chain). Its order differs from plan.list's, and is the same at every level.
  std::fill(next.begin(), next.end(), 0);
  for (std::size_t i = 0; i < m; ++i) ++next[(i & 3) * steps + a.k[i]];
  std::size_t at = 0;
  for (std::size_t j = 0; j < steps; ++j) {
    first[j] = at;
    for (std::size_t row = 0; row < 4; ++row) {
      const std::size_t count = next[row * steps + j];
      next[row * steps + j] = at;
      at += count;
    }
  }
  first[steps] = at;
  for (std::size_t i = 0; i < m; ++i)
    order[next[(i & 3) * steps + a.k[i]]++] = static_cast<std::uint32_t>(i);
}

bool escaped(double x, double y) {
  return !(std::abs(x) < kEscape && std::abs(y) < kEscape);
}

// Walkers that no longer plot (past their limit, or last moved by an invisible xform) off.
void unplotted(const Plan& plan, const Walkers& a, std::size_t m, std::uint64_t s,
               std::array<std::uint32_t, kN>& at) {
  if (s < a.first_limit && !plan.any_invisible) return;
  // Without branches (as bits: GCC made branches of a select): the xform a walker picked is
  // random, and so was the branch on it (a tenth of a linear flame's walk with invisible
  // xforms, perf at 27 Nov 19:45).
  const std::uint8_t* invisible = plan.invisible.data();
  for (std::size_t i = 0; i < m; ++i) {
    const auto off = static_cast<std::uint32_t>(s >= a.limit[i]) | invisible[a.k[i]];
    at[i] |= 0u - off;  // kOffBin: all ones
  }
}

// Walkers that escaped re-seeded (in walker order, as the generator's draws must be); how many.
std::uint64_t reseed(Walkers& a, std::size_t m, std::array<bool, kN>* out, Rng& rng) {
  std::uint64_t reseeded = 0;
  for (std::size_t i = 0; i < m; ++i) {
    if (!escaped(a.x[i], a.y[i])) continue;
    if (out) (*out)[i] = true;
    start(a, i, rng);
    ++reseeded;
  }
  return reseeded;
}

// After step `s` of every walker: escapees re-seeded, the others plotted (through the final
// xform, when there is one, which moves the plotted copy only).
std::uint64_t plot_walkers(const Plan& plan, Walkers& a, std::size_t m, std::uint64_t s,
                           std::uint64_t burn_in, Scratch& w, Rng& rng, Bins& bins) {
  std::array<std::uint32_t, kN> at;
  if (!plan.final_step) {
    // The bins first: an escaped walker's is kOffBin, and its new start is not plotted.
    const std::size_t gone = plan.bin_numbers(plan.grid, m, a.x.data(), a.y.data(), at.data());
    const std::uint64_t reseeded = gone == 0 ? 0 : reseed(a, m, nullptr, rng);
    if (s < burn_in) return reseeded;
    unplotted(plan, a, m, s, at);
    plot_all(plan, at, a.k, a.c, m, bins);
    return reseeded;
  }
  std::array<bool, kN> out{};
  const std::uint64_t reseeded = reseed(a, m, &out, rng);
  if (s < burn_in) return reseeded;
  std::array<double, kN> fx = a.x, fy = a.y, fc{};
  plan.final_step->motion(m, fx.data(), fy.data(), w, rng);
  const Step& f = *plan.final_step;
  plan.bin_numbers(plan.grid, m, fx.data(), fy.data(), at.data());
  unplotted(plan, a, m, s, at);
  for (std::size_t i = 0; i < m; ++i) {
    if (out[i]) at[i] = kOffBin;
    fc[i] = f.keep * a.c[i] + f.shift;
  }
  plot_all(plan, at, a.k, fc, m, bins);
  return reseeded;
}

// One chunk: up to kBatchLanes walkers of kWalkerPoints points (the last one of the run may have
// fewer), each from a random start, burn_in iterations unplotted, walked in lockstep.
std::uint64_t walk_chunk(const Plan& plan, std::uint64_t seed, std::uint64_t chunk, std::uint64_t n,
                         int burn_in, Bins& bins) {
  Rng rng(stream_seed(seed, chunk));
  const auto burn = static_cast<std::uint64_t>(burn_in);
  const std::size_t m = static_cast<std::size_t>((n + kWalkerPoints - 1) / kWalkerPoints);
  auto walkers = std::make_unique<Walkers>();
  Walkers& a = *walkers;
  for (std::size_t i = 0; i < m; ++i) {
    start(a, i, rng);
    a.limit[i] = burn + std::min(kWalkerPoints, n - i * kWalkerPoints);
  }
  a.first_limit =
      *std::min_element(a.limit.begin(), a.limit.begin() + static_cast<std::ptrdiff_t>(m));
  Scratch w;
  std::vector<std::size_t> first(plan.steps.size() + 1), next(4 * plan.steps.size());
  std::array<std::uint32_t, kN> order{};
  std::uint64_t reseeded = 0;
  for (std::uint64_t s = 0; s < burn + kWalkerPoints; ++s) {
    pick(plan, a, m, first, next, order, rng);
    for (std::size_t j = 0; !plan.affine_only && j + 1 < first.size(); ++j) {
      const std::size_t lo = first[j], count = first[j + 1] - lo;
      if (count == 0) continue;
      const Step& step = plan.steps[j];
      const std::uint32_t* at = order.data() + lo;
      step.motion(count, at, a.x.data(), a.y.data(), w, rng);
      // (keep and shift in registers: a store to a.c might otherwise change them)
      const double keep = step.keep, shift = step.shift;
      for (std::size_t i = 0; i < count; ++i) a.c[at[i]] = keep * a.c[at[i]] + shift;
    }
    reseeded += plot_walkers(plan, a, m, s, burn, w, rng, bins);
  }
  return reseeded;
}

// The Flat records of an affine_only plan whose sums have at most kFlatTerms terms, and the
// shape they share.
void flatten(Plan& plan) {
  bool one_term = true, post = true, no_post = true;
  for (const Step& step : plan.steps) {
    const XformStep& s = step.motion;
    if (s.sum_terms.size() > kFlatTerms) {
      plan.flat.clear();
      return;
    }
    Flat f{.pre = PairMap(s.pre),
           .post = PairMap(s.post),
           .keep = step.keep,
           .shift = step.shift,
           .terms = static_cast<std::uint32_t>(s.sum_terms.size()),
           .has_sum = s.has_sum,
           .has_post = s.has_post};
    for (std::size_t t = 0; t < s.sum_terms.size(); ++t)
      f.w[t] = D2{s.sum_terms[t].w, s.sum_terms[t].w};
    plan.flat.push_back(f);
    one_term = one_term && s.has_sum && s.sum_terms.size() == 1;
    post = post && s.has_post;
    no_post = no_post && !s.has_post;
  }
  plan.flat_shape = !one_term ? FlatShape::any
                    : post    ? FlatShape::one_term_post
                    : no_post ? FlatShape::one_term
                              : FlatShape::any;
}

// Where every xform sets the colour coordinate to its own (keep 0) and no final xform moves it,
// a plotted walker's coordinate is 0·c + shift = shift of the xform that moved it last (c ≥ 0,
// and every plotted walker has moved since its start): its hit's colour is fixed per xform,
// computed here by the plot kernel itself from that coordinate.
void fix_colours(Plan& plan) {
  if (plan.final_step ||
      std::any_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return s.keep != 0; }))
    return;
  const std::size_t n = plan.steps.size();
  plan.fixed.assign(4 * n, 0);
  std::vector<std::uint32_t> at(n), k(n);
  std::vector<double> c(n);
  for (std::size_t j = 0; j < n; ++j) {
    at[j] = static_cast<std::uint32_t>(j);
    k[j] = static_cast<std::uint32_t>(j);
    c[j] = plan.steps[j].shift;
  }
  unsigned wrapped = 0;
  plan.plot(plan.tables, plan.fixed.data(), 0, n, nullptr, at.data(), k.data(), c.data(), &wrapped);
  plan.tables.fixed = plan.fixed.data();
}

Plan plan_of(const Flame& flame, const FlameRaster& raster, bool float_lanes) {
  Plan plan;
  const Kernels kernels{cpu_level(), float_lanes ? LaneType::f32 : LaneType::f64};
  for (const Xform& xf : flame.xforms) plan.steps.push_back(step_of(xf, flame.palette, kernels));
  if (flame.final_xform) plan.final_step = step_of(*flame.final_xform, flame.palette, kernels);
  plan.pickers = xform_pickers(flame, false);
  plan.affine_only = std::all_of(plan.steps.begin(), plan.steps.end(),
                                 [](const Step& s) { return s.motion.affine_only; });
  if (plan.affine_only) flatten(plan);
  plan.linear_palette = flame.palette.mode == PaletteMode::linear;
  // A bin's number and kOffBin fit 32 bits (a raster that large would need 64 GiB a worker).
  const std::uint64_t bins = std::uint64_t{static_cast<std::uint32_t>(raster.bins_x)} *
                             static_cast<std::uint32_t>(raster.bins_y);
  if (bins >= kOffBin)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("flame raster: at most {} bins (got {})", kOffBin - 1, bins));
  plan.grid = {raster.to_bins, static_cast<std::uint32_t>(raster.bins_x),
               static_cast<std::uint32_t>(raster.bins_y)};
  plan.bin_numbers = bin_function(cpu_level());
  for (const Step& s : plan.steps) {
    plan.invisible.push_back(s.invisible ? 1 : 0);
    plan.any_invisible = plan.any_invisible || s.invisible;
    plan.colours.push_back(reinterpret_cast<const std::uint32_t*>(s.colours.data()));
  }
  plan.tables = {plan.colours.data(), plan.linear_palette};
  plan.plot = plot_function(cpu_level());
  plan.hits = hits_function(cpu_level());
  plan.list = list_function(cpu_level());
  fix_colours(plan);
  return plan;
}

}  // namespace

ChaosResult run_chaos_game(const ChaosRun& run) {
  const Plan plan = plan_of(*run.flame, run.raster, run.float_lanes);
  const std::uint64_t chunks =
      std::max<std::uint64_t>(1, (run.points + kChunkPoints - 1) / kChunkPoints);
  const int workers = worker_count(chunks, run.threads);
  // Each worker's bins built in place (copies of one prototype would zero, fault in and copy
  // one raster more).
  std::vector<Bins> bins;
  bins.reserve(static_cast<std::size_t>(workers));
  for (int w = 0; w < workers; ++w) bins.emplace_back(run.raster);
  std::vector<std::uint64_t> reseeded(chunks, 0);
  std::atomic<std::uint64_t> done{0};
  std::mutex progress_mutex;
  parallel_for(chunks, workers, [&](std::size_t chunk, int worker) {
    run.cancel.check("render");
    const std::uint64_t first = chunk * kChunkPoints;
    const std::uint64_t n = std::min(kChunkPoints, run.points - std::min(run.points, first));
    reseeded[chunk] =
        walk_chunk(plan, run.seed, chunk, n, run.burn_in, bins[static_cast<std::size_t>(worker)]);
    const std::uint64_t finished = ++done;
    if (run.progress) {
      std::lock_guard lock(progress_mutex);
      run.progress(static_cast<double>(finished) / static_cast<double>(chunks));
    }
  });
  ChaosResult out{FlameHistogram(run.raster.bins_x, run.raster.bins_y), 0};
  for (std::uint64_t r : reseeded) out.reseeded += r;
  for (std::size_t i = 0; i < out.histogram.rgba.size(); ++i) {
    std::uint64_t sum = 0;
    for (const Bins& b : bins) sum += b.lo[i];
    out.histogram.rgba[i] = static_cast<double>(sum) / kUnit;
  }
  for (const Bins& b : bins)
    for (std::size_t i : b.carries) out.histogram.rgba[i] += 0x1p32 / kUnit;
  return out;
}

}  // namespace ifsfx::flame::detail
