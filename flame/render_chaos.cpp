// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "flame/detail/render_chaos.h"
#include "flame/variations.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::flame::detail {
namespace {

// flam3's sub-batch: each walker plots this many points from its own random start. Flames
// whose maps do not contract (a pure rotation draws one circle per start) show the count.
constexpr std::uint64_t kChunkPoints = 10000;
constexpr double kUnit = 65536;   // one hit of full colour, in the integer sums
constexpr double kEscape = 1e10;  // a point beyond this (or not a number) is re-seeded

// One variation term with everything the inner loop needs resolved once.
struct Term {
  VariationFunction f;
  double w;
  std::span<const double> params;
  bool adds;  // pre_/post_ lists: p + w·V(p) rather than w·V(p)
};

// An xform prepared for the loop: apply_xform's steps (flame/xform_eval.h) without looking
// anything up, and the colour update c ← keep·c + shift.
struct Step {
  AffineMap pre, post;
  bool has_post = false, has_sum = false;
  std::vector<Term> pre_terms, sum_terms, post_terms;
  double keep = 1, shift = 0;
  std::array<std::array<std::uint32_t, 4>, 256> colours{};  // palette × opacity, in kUnit

  Point chain(const std::vector<Term>& terms, Point q, Rng& rng) const {
    for (const Term& t : terms) {
      const Point r = t.f({.p = q, .w = t.w, .params = t.params, .pre = &pre}, rng);
      q = t.adds ? Point{q.x + r.x, q.y + r.y} : r;
    }
    return q;
  }
  Point operator()(Point p, Rng& rng) const {
    Point q = chain(pre_terms, pre(p), rng);
    Point s = q;
    if (has_sum) {
      s = {0, 0};
      for (const Term& t : sum_terms) {
        const Point v = t.f({.p = q, .w = t.w, .params = t.params, .pre = &pre}, rng);
        s = {s.x + v.x, s.y + v.y};
      }
    }
    if (has_post) s = post(s);
    return chain(post_terms, s, rng);
  }
};

std::vector<Term> terms_of(const std::vector<VariationTerm>& list, bool in_sum) {
  std::vector<Term> out;
  for (const VariationTerm& t : list) {
    const Variation& v = variation(t.id);
    // z only: adds nothing to the sum, leaves the point alone in a list.
    if (v.kind == VariationKind::flat_3d) continue;
    out.push_back({v.function, t.weight, t.params, !in_sum && v.assign == Assign::add});
  }
  return out;
}

Step step_of(const Xform& xf, const Palette& palette) {
  Step s;
  s.pre = xf.pre;
  s.has_post = xf.post.has_value();
  if (s.has_post) s.post = *xf.post;
  s.has_sum = !xf.variations.empty();
  s.pre_terms = terms_of(xf.pre_variations, false);
  s.sum_terms = terms_of(xf.variations, true);
  s.post_terms = terms_of(xf.post_variations, false);
  s.keep = 1 - xf.colour_speed;
  s.shift = xf.colour_speed * xf.colour;
  for (std::size_t i = 0; i < 256; ++i) {
    const Rgba& c = palette.colours[i];
    const double k = xf.opacity * c.a * kUnit;
    // The colour channels carry the palette's alpha too: flam3 adds the entry premultiplied.
    s.colours[i] = {static_cast<std::uint32_t>(std::lround(c.r * k)),
                    static_cast<std::uint32_t>(std::lround(c.g * k)),
                    static_cast<std::uint32_t>(std::lround(c.b * k)),
                    static_cast<std::uint32_t>(std::lround(k))};
  }
  return s;
}

// The xform pickers: [0] by the weights alone, [1 + i] after xform i by weight × chaos row i
// (a row of zeros falls back to the weights).
std::vector<MapPicker> pickers_of(const Flame& flame) {
  std::vector<double> weights;
  bool xaos = false;
  for (const Xform& xf : flame.xforms) {
    weights.push_back(xf.weight);
    for (double c : xf.chaos) xaos = xaos || c != 1;
  }
  std::vector<MapPicker> out{MapPicker(weights)};
  if (!xaos) return out;
  for (const Xform& from : flame.xforms) {
    std::vector<double> row = weights;
    double sum = 0;
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (j < from.chaos.size()) row[j] *= from.chaos[j];
      sum += row[j];
    }
    out.emplace_back(sum > 0 ? row : weights);
  }
  return out;
}

struct Plan {
  std::vector<Step> steps;
  std::optional<Step> final_step;
  std::vector<MapPicker> pickers;
  bool linear_palette = false;
  std::array<Rgba, 256> palette{};
  FlameRaster raster;
};

// The histogram of one worker: r, g, b, a integer sums per bin.
struct Bins {
  std::vector<std::uint64_t> sums;
  explicit Bins(const FlameRaster& r) : sums(4 * static_cast<std::size_t>(r.bins_x) * r.bins_y) {}
};

void plot(const Plan& plan, const Step& from, Point p, double c, Bins& bins) {
  const FlameRaster& r = plan.raster;
  const Point b = r.to_bins(p);
  if (!(b.x >= 0 && b.x < r.bins_x && b.y >= 0 && b.y < r.bins_y)) return;
  std::uint64_t* bin =
      &bins.sums[4 * (static_cast<std::size_t>(b.y) * r.bins_x + static_cast<std::size_t>(b.x))];
  c = std::clamp(c, 0.0, 1.0);
  if (!plan.linear_palette) {
    // Step palette: entry ⌊256·c⌋, the last one for c = 1.
    const auto& e = from.colours[std::min<std::size_t>(static_cast<std::size_t>(c * 256), 255)];
    for (int k = 0; k < 4; ++k) bin[k] += e[static_cast<std::size_t>(k)];
    return;
  }
  // Linear palette: entries ⌊256·c⌋ and the next, mixed by the fraction, in 1/256 steps
  // (integers, no rounding call in the loop); from 255 on, the last entry. flam3-render's
  // colours of Fractorium's linear-palette flames say 256·c, not 255·c.
  const auto x = static_cast<std::uint32_t>(std::min(c * 256, 255.0) * 256);
  const std::size_t i = std::min<std::uint32_t>(x >> 8, 254);
  const std::uint64_t w = x - (static_cast<std::uint32_t>(i) << 8);
  const auto& e0 = from.colours[i];
  const auto& e1 = from.colours[i + 1];
  for (std::size_t k = 0; k < 4; ++k) bin[k] += (e0[k] * (256 - w) + e1[k] * w) >> 8;
}

// One chunk: a walker from a random start in [−1, 1]² (colour random in [0, 1)), burn_in
// iterations unplotted, then n plotted ones; the final xform moves the plotted copy only.
std::uint64_t walk_chunk(const Plan& plan, std::uint64_t seed, std::uint64_t chunk, std::uint64_t n,
                         int burn_in, Bins& bins) {
  Rng rng(stream_seed(seed, chunk));
  const auto start = [&](Point& p, double& c) {
    p = {2 * rng.uniform() - 1, 2 * rng.uniform() - 1};
    c = rng.uniform();
  };
  Point p;
  double c;
  start(p, c);
  std::uint64_t reseeded = 0;
  std::size_t picker = 0;
  const std::uint64_t total = n + static_cast<std::uint64_t>(burn_in);
  for (std::uint64_t i = 0; i < total; ++i) {
    const std::uint32_t k = plan.pickers[picker](rng.next());
    if (plan.pickers.size() > 1) picker = 1 + k;
    const Step& step = plan.steps[k];
    const Point q = step(p, rng);
    if (!(std::abs(q.x) < kEscape && std::abs(q.y) < kEscape)) {
      start(p, c);
      ++reseeded;
      continue;
    }
    p = q;
    c = step.keep * c + step.shift;
    if (i < static_cast<std::uint64_t>(burn_in)) continue;
    if (!plan.final_step) {
      plot(plan, step, p, c, bins);
      continue;
    }
    const Point f = (*plan.final_step)(p, rng);
    if (std::abs(f.x) < kEscape && std::abs(f.y) < kEscape)
      plot(plan, step, f, plan.final_step->keep * c + plan.final_step->shift, bins);
  }
  return reseeded;
}

Plan plan_of(const Flame& flame, const FlameRaster& raster) {
  Plan plan;
  for (const Xform& xf : flame.xforms) plan.steps.push_back(step_of(xf, flame.palette));
  if (flame.final_xform) plan.final_step = step_of(*flame.final_xform, flame.palette);
  plan.pickers = pickers_of(flame);
  plan.linear_palette = flame.palette.mode == PaletteMode::linear;
  plan.raster = raster;
  return plan;
}

}  // namespace

ChaosResult run_chaos_game(const ChaosRun& run) {
  const Plan plan = plan_of(*run.flame, run.raster);
  const std::uint64_t chunks =
      std::max<std::uint64_t>(1, (run.points + kChunkPoints - 1) / kChunkPoints);
  const int workers = worker_count(chunks, run.threads);
  std::vector<Bins> bins(static_cast<std::size_t>(workers), Bins(run.raster));
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
    for (const Bins& b : bins) sum += b.sums[i];
    out.histogram.rgba[i] = static_cast<double>(sum) / kUnit;
  }
  return out;
}

}  // namespace ifsfx::flame::detail
