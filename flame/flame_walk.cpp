// SPDX-License-Identifier: Apache-2.0
// The batched chaos game of the paper's modes (flame/detail/flame_walk.h).
#include "flame/detail/flame_walk.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "flame/xform_pickers.h"
#include "ifs/cpu.h"
#include "ifs/detail/address_raster.h"

namespace ifsfx::flame::detail {
namespace {

constexpr std::size_t kN = kStepStride;

bool escaped(double x, double y) {
  return !(std::abs(x) < kEscape && std::abs(y) < kEscape);
}

}  // namespace

// The walkers of one chunk, in the flame plane. They stay in place; `live` lists those that
// still plot, in walker order.
struct FlameWalk::Walkers {
  std::array<double, kN> x{}, y{};
  std::array<std::uint64_t, kN> key{};     // the address: the last symbols, newest on top
  std::array<std::uint64_t, kN> left{};    // points still to plot
  std::array<std::uint32_t, kN> row{};     // the picker row: 0 from a start, 1 + σ after σ (xaos)
  std::array<std::uint32_t, kN> k{};       // the xform picked this step
  std::array<int, kN> burn{};              // steps still unplotted
  std::array<std::uint64_t, kN> budget{};  // steps it may still take (kStepBudget)
  std::array<std::uint32_t, kN> live{}, order{}, plotted{};
  std::size_t n_live = 0;
  bool gave_up = false;        // a walker gave up this step: the live list is to be pruned
  std::uint64_t given_up = 0;  // the points the walkers that gave up had left
  std::vector<std::size_t> first, next;  // the counting sort's, per xform

  // Walker i from a uniform point of [−1, 1]², its address forgotten.
  void start(std::size_t i, int burn_in, Rng& rng) {
    x[i] = 2 * rng.uniform() - 1;
    y[i] = 2 * rng.uniform() - 1;
    key[i] = 0;
    row[i] = 0;
    burn[i] = burn_in;
  }
};

FlameWalk::FlameWalk(const WalkSetup& setup)
    : pickers_(xform_pickers(*setup.flame, true)),
      turn_(setup.turn),
      sx_(setup.to_pixel.a),
      ox_(setup.to_pixel.e),
      sy_(setup.to_pixel.d),
      oy_(setup.to_pixel.f),
      width_(setup.width),
      height_(setup.height),
      burn_in_(setup.burn_in),
      bits_(ifsfx::detail::symbol_bits(setup.flame->xforms.size())) {
  const Kernels kernels{cpu_level(), setup.lanes};
  for (const Xform& xf : setup.flame->xforms) steps_.push_back(xform_step_of(xf, kernels));
  if (setup.flame->final_xform) final_ = xform_step_of(*setup.flame->final_xform, kernels);
}

// Each live walker picks its xform and moves through it, the walkers of one xform together
// (a counting sort of the live list by xform); escapees re-seeded, the others' keys take the
// symbol and count down their burn-in. Returns how many plot this step (a.plotted).
std::size_t FlameWalk::move(Walkers& a, Scratch& w, Rng& rng) const {
  // Locals, not members: the stores through a's arrays would otherwise reload them every walker.
  const std::size_t steps = steps_.size(), live = a.n_live;
  const bool xaos = pickers_.size() > 1;
  std::size_t* next = a.next.data();
  std::fill_n(next, steps, 0);
  MapPicker::View v = pickers_[0].view();
  for (std::size_t l = 0; l < live; ++l) {
    const std::uint32_t i = a.live[l];
    if (xaos) v = pickers_[a.row[i]].view();
    a.k[i] = v.branch_free(rng.next());
    ++next[a.k[i]];
  }
  std::size_t at = 0;
  for (std::size_t j = 0; j < steps; ++j) {
    a.first[j] = at;
    at += std::exchange(next[j], at);
  }
  a.first[steps] = at;
  for (std::size_t l = 0; l < live; ++l) a.order[next[a.k[a.live[l]]]++] = a.live[l];
  for (std::size_t j = 0; j < steps; ++j)
    if (a.first[j + 1] > a.first[j])
      steps_[j](a.first[j + 1] - a.first[j], a.order.data() + a.first[j], a.x.data(), a.y.data(), w,
                rng);
  const int shift = 64 - bits_;
  std::size_t plotted = 0;
  for (std::size_t l = 0; l < live; ++l) {
    const std::uint32_t i = a.live[l];
    if (--a.budget[i] == 0) {
      a.given_up += std::exchange(a.left[i], 0);
      a.gave_up = true;
      continue;
    }
    if (escaped(a.x[i], a.y[i])) {
      a.start(i, burn_in_, rng);
      continue;
    }
    a.key[i] = (a.key[i] >> bits_) | (std::uint64_t{a.k[i]} << shift);
    if (xaos) a.row[i] = 1 + a.k[i];
    if (a.burn[i] > 0) {
      --a.burn[i];
      continue;
    }
    a.plotted[plotted++] = i;
  }
  return plotted;
}

// The step's plotting walkers' points through the final xform (a copy: the walkers go on from
// their own points), flipped into the IFS plane, turned, onto the raster.
void FlameWalk::plot_step(Walkers& a, std::size_t plotted, Scratch& w, Rng& rng,
                          WalkHits& hits) const {
  std::array<double, kN> fx, fy;
  for (std::size_t p = 0; p < plotted; ++p) {
    fx[p] = a.x[a.plotted[p]];
    fy[p] = a.y[a.plotted[p]];
  }
  if (final_) (*final_)(plotted, fx.data(), fy.data(), w, rng);
  hits.n = 0;
  for (std::size_t p = 0; p < plotted; ++p) {
    Point x{fx[p], -fy[p]};
    if (turn_) x = (*turn_)(x);
    // The kernels' pixel mapping, to the bit: px = sx·x + ox, py = sy·y + oy.
    const double px = sx_ * x.x + ox_, py = sy_ * x.y + oy_;
    if ((px >= 0) & (px < width_) & (py >= 0) & (py < height_)) {
      hits.pixel[hits.n] = static_cast<long>(py) * width_ + static_cast<long>(px);
      hits.key[hits.n++] = a.key[a.plotted[p]];
    }
  }
}

std::uint64_t FlameWalk::walk(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                              const std::function<void(const WalkHits&)>& plot) const {
  if (points == 0) return 0;
  Rng rng(stream_seed(seed, chunk));
  const auto m = static_cast<std::size_t>(
      std::min<std::uint64_t>(kBatchLanes, (points + kWalkerPlots - 1) / kWalkerPlots));
  const auto a = std::make_unique<Walkers>();
  a->first.resize(steps_.size() + 1);
  a->next.resize(steps_.size());
  for (std::size_t i = 0; i < m; ++i) {
    a->start(i, burn_in_, rng);
    a->left[i] = points / m + (i < points % m ? 1 : 0);
    a->budget[i] = kStepBudget * (a->left[i] + static_cast<std::uint64_t>(burn_in_));
    a->live[i] = static_cast<std::uint32_t>(i);
  }
  a->n_live = m;
  Scratch w;
  const auto hits = std::make_unique<WalkHits>();
  while (a->n_live > 0) {
    const std::size_t plotted = move(*a, w, rng);
    if (plotted == 0 && !a->gave_up) continue;
    if (plotted > 0) {
      plot_step(*a, plotted, w, rng, *hits);
      if (hits->n > 0) plot(*hits);
    }
    // The walkers done (or given up) leave the live list, which keeps its order.
    for (std::size_t p = 0; p < plotted; ++p) --a->left[a->plotted[p]];
    a->gave_up = false;
    a->n_live = static_cast<std::size_t>(
        std::remove_if(a->live.begin(), a->live.begin() + static_cast<std::ptrdiff_t>(a->n_live),
                       [&](std::uint32_t i) { return a->left[i] == 0; }) -
        a->live.begin());
  }
  return a->given_up;
}

}  // namespace ifsfx::flame::detail
