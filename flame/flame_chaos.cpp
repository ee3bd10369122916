// SPDX-License-Identifier: Apache-2.0
// A flame's attractor, tops and steal map by ifsfx's chaos game (flame/flame_chaos.h).
#include "flame/flame_chaos.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "flame/detail/flame_walk.h"
#include "flame/render_camera.h"
#include "flame/xform_eval.h"
#include "flame/xform_pickers.h"
#include "ifs/detail/address_raster.h"
#include "ifs/detail/preconditions.h"
#include "ifs/detail/walkers.h"
#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::flame {
namespace {

// A point beyond flame::detail::kEscape (or not a number) has left the flame: its walker starts
// again (the renderer's rule and bound).
using flame::detail::kEscape;
// Burn-in of a flame that is not an affine IFS: no contraction factor says how long the walk
// takes to forget its start; flam3 discards 15, the affine chaos game at least 64.
constexpr int kFlameBurnIn = 64;

// The flame plane's y points down, the IFS plane's up: S(x, y) = (x, −y), its own inverse.
Point flip(Point p) {
  return {p.x, -p.y};
}

// The camera at `size`: the framing kept, the scale following the width (render_flame's rule).
Camera sized_camera(const Flame& flame, cv::Size size) {
  Camera camera = flame.camera;
  if (size.width != camera.width || size.height != camera.height) {
    camera.scale *= static_cast<double>(size.width) / camera.width;
    camera.width = size.width;
    camera.height = size.height;
  }
  return camera;
}

// The walkers of an affine IFS drawn as a flame (affine_ifs) on one viewport: the affine
// kernels' lanes (ifs/detail/walkers.h) — each lane starts at a uniform point of [0, 1)² from its
// own xoshiro256+, picks every xform with one draw of it, burns in, then plots — with the
// xform's step in place of the affine map, so that the pictures are the affine IFS's bytes.
// Lanes run one after another: what they plot is merged by max or OR, which ignores the order.
// Every other flame takes the batched walk (flame/detail/flame_walk.h).
class LaneWalk {
 public:
  LaneWalk(const Flame& flame, const Viewport& viewport, const std::optional<AffineMap>& turn,
           int burn_in)
      : flame_(flame), pickers_(xform_pickers(flame, true)), turn_(turn), burn_in_(burn_in) {
    const AffineMap to_pixel = viewport.plane_to_pixel();
    sx_ = to_pixel.a, ox_ = to_pixel.e, sy_ = to_pixel.d, oy_ = to_pixel.f;
    width_ = viewport.size.width;
    height_ = viewport.size.height;
    bits_ = ifsfx::detail::symbol_bits(flame.xforms.size());
  }

  // `points` points of chunk `chunk`: plot(pixel, key) for each that lands on the raster, its
  // address key (σk in the top b bits, docs/design.md §2). Returns the points given up.
  template <class Plot>
  std::uint64_t walk(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     Plot&& plot) const {
    const ifsfx::detail::LaneSeeds seeds = ifsfx::detail::lane_seeds(seed, chunk);
    std::uint64_t given_up = 0;
    for (int lane = 0; lane < ifsfx::detail::kLanes; ++lane) {
      const std::uint64_t n =
          points / ifsfx::detail::kLanes +
          (static_cast<std::uint64_t>(lane) < points % ifsfx::detail::kLanes ? 1 : 0);
      given_up += walk_lane(seeds.s[lane], n, plot);
    }
    return given_up;
  }

 private:
  // The lane's n points; returns those it gave up.
  template <class Plot>
  std::uint64_t walk_lane(const std::uint64_t (&state)[4], std::uint64_t n, Plot& plot) const {
    ifsfx::detail::LaneRng rng(state);
    Rng variations(stream_seed(state[0], state[1]));
    const int shift = 64 - bits_;
    Point p;
    std::uint64_t key = 0;
    std::size_t picker = 0;
    int burn = 0;
    const auto start = [&] {
      const double x = rng.unit();
      p = {x, rng.unit()};
      key = 0;
      picker = 0;
      burn = burn_in_;
    };
    start();
    // Bounded as the batched walk's walkers are (flame::detail::kStepBudget): a flame that
    // escapes for ever gives up the lane's points.
    std::uint64_t budget = flame::detail::kStepBudget * (n + static_cast<std::uint64_t>(burn_in_));
    for (std::uint64_t plotted = 0; plotted < n;) {
      if (budget-- == 0) return n - plotted;
      const std::uint32_t k = pickers_[picker](rng.next());
      if (pickers_.size() > 1) picker = 1 + k;
      const Point q = flip(apply_xform(flame_.xforms[k], flip(p), variations));
      if (!(std::abs(q.x) < kEscape && std::abs(q.y) < kEscape)) {
        start();
        continue;
      }
      p = q;
      key = (key >> bits_) | (static_cast<std::uint64_t>(k) << shift);
      if (burn > 0) {
        --burn;
        continue;
      }
      ++plotted;
      Point x = p;
      if (flame_.final_xform) x = flip(apply_xform(*flame_.final_xform, flip(x), variations));
      if (turn_) x = (*turn_)(x);
      // The kernels' pixel mapping, to the bit: px = sx·x + ox, py = sy·y + oy.
      const double px = sx_ * x.x + ox_, py = sy_ * x.y + oy_;
      if ((px >= 0) & (px < width_) & (py >= 0) & (py < height_))
        plot(static_cast<long>(py) * width_ + static_cast<long>(px), key);
    }
    return 0;
  }

  const Flame& flame_;
  std::vector<MapPicker> pickers_;
  std::optional<AffineMap> turn_;
  int burn_in_;
  double sx_ = 0, ox_ = 0, sy_ = 0, oy_ = 0;
  int width_ = 0, height_ = 0;
  int bits_ = 1;
};

// Everything a picture of a flame needs: its viewport, its affine IFS when it is one that
// contracts (then the affine chaos game's Hutchinson passes, burn-in and pixel-centre steal
// apply), and the camera's turn of the plotted points.
struct Plan {
  Viewport viewport;
  std::optional<Ifs> affine;
  std::optional<AffineMap> turn;
  bool lanes = false;  // an affine IFS (contracting or not): the affine kernels' lanes
};

Plan plan_of(const Flame& flame, cv::Size size, const Sampling& sampling) {
  Plan plan{flame_viewport(flame, size, sampling), affine_ifs(flame), std::nullopt, false};
  plan.lanes = plan.affine.has_value();
  if (plan.affine && !(plan.affine->contraction() < 1)) plan.affine.reset();
  if (!sampling.view && flame.camera.rotate != 0) {
    // The camera's bins (flame plane → pixels, turned) against the unturned viewport: the turn
    // in the IFS plane is V⁻¹ ∘ M ∘ S.
    const AffineMap M = flame_raster(sized_camera(flame, size), 1, 0).to_bins;
    const AffineMap S{1, 0, 0, -1, 0, 0};
    plan.turn = plan.viewport.plane_to_pixel().inverse(0)->compose(M).compose(S);
  }
  return plan;
}

// Points a chunk of the walk plots: an affine IFS's chunks (its pictures are then the affine
// chaos game's, byte for byte; smaller ones where it does not contract, as before the batched
// walk), the batched walk's for any other flame.
std::uint64_t chunk_points(const Plan& plan) {
  if (!plan.lanes) return flame::detail::kWalkChunkPoints;
  return plan.affine ? ifsfx::detail::kChunkPoints : ifsfx::detail::kSlowChunkPoints;
}

// The walk of a plan: the affine lanes or the batched walk, plot(pixel, key) for every point
// that lands on the raster.
class Walk {
 public:
  Walk(const Flame& flame, const Plan& plan, int burn_in) {
    if (plan.lanes) {
      lanes_.emplace(flame, plan.viewport, plan.turn, burn_in);
      return;
    }
    batch_.emplace(flame::detail::WalkSetup{.flame = &flame,
                                            .to_pixel = plan.viewport.plane_to_pixel(),
                                            .turn = plan.turn,
                                            .width = plan.viewport.size.width,
                                            .height = plan.viewport.size.height,
                                            .burn_in = burn_in});
  }

  template <class Plot>
  void walk(std::uint64_t seed, std::uint64_t chunk, std::uint64_t points, Plot&& plot) const {
    if (lanes_) {
      given_up_ += lanes_->walk(seed, chunk, points, plot);
      return;
    }
    given_up_ += batch_->walk(seed, chunk, points, [&plot](const flame::detail::WalkHits& hits) {
      for (std::size_t i = 0; i < hits.n; ++i) plot(hits.pixel[i], hits.key[i]);
    });
  }

  // The points the walks so far gave up (their walkers' step budget ran out), of any thread: a
  // sum of integers, the same whatever the order.
  std::uint64_t given_up() const { return given_up_; }

 private:
  std::optional<LaneWalk> lanes_;
  std::optional<flame::detail::FlameWalk> batch_;
  mutable std::atomic<std::uint64_t> given_up_{0};
};

void check_inputs(const Flame& flame, cv::Size size, const Sampling& sampling, bool exact) {
  check_flame_chaos(sampling, exact);
  if (flame.xforms.empty())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("flame \"{}\": has no xform (got 0)", flame.name));
  Ifs pre;
  for (const Xform& xf : flame.xforms) {
    pre.maps.push_back(xf.pre);
    pre.probabilities.push_back(xf.weight);
  }
  pre.name = flame.name.empty() ? "flame" : flame.name;
  ifsfx::detail::check_chaos_game({.ifs = pre, .size = size, .sampling = &sampling});
}

// The tops keys of a flame on its plan: the affine coverage policy over the flame's walk.
ifsfx::detail::AddressRaster flame_keys(const Flame& flame, const Plan& plan,
                                        const Sampling& sampling, int key_bits,
                                        ifsfx::detail::ChaosTopsStats* stats) {
  const int bits = ifsfx::detail::symbol_bits(flame.xforms.size());
  const int burn_in =
      std::max(plan.affine ? default_burn_in(*plan.affine) : kFlameBurnIn, 64 / bits + 1);
  const auto walk = std::make_shared<const Walk>(flame, plan, burn_in);
  const auto run = [walk](auto* cells, std::uint64_t seed, std::uint64_t chunk,
                          std::uint64_t points) {
    using Cell = std::remove_pointer_t<decltype(cells)>;
    constexpr int kShift = 64 - 8 * static_cast<int>(sizeof(Cell));
    walk->walk(seed, chunk, points, [cells](long pixel, std::uint64_t key) {
      // Top keeps the larger address (eq. 7): each pixel keeps its largest key.
      const Cell v = static_cast<Cell>(key >> kShift) | 1;
      if (v > cells[pixel]) cells[pixel] = v;
    });
  };
  const ifsfx::detail::KeyWalk keys{
      .run32 = [run](std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     std::uint32_t* cells) { run(cells, seed, chunk, points); },
      .run64 = [run](std::uint64_t seed, std::uint64_t chunk, std::uint64_t points,
                     std::uint64_t* cells) { run(cells, seed, chunk, points); },
      .bits = bits,
      .chunk_points = chunk_points(plan),
      .affine = plan.affine ? &*plan.affine : nullptr};
  ifsfx::detail::AddressRaster out = ifsfx::detail::chaos_tops(keys, plan.viewport,
                                                               {.quality = sampling.quality,
                                                                .seed = sampling.seed,
                                                                .threads = sampling.threads,
                                                                .key_bits = key_bits,
                                                                .cancel = sampling.cancel},
                                                               stats);
  if (stats) stats->points -= walk->given_up();
  return out;
}

// T of each covered pixel from its whole key: g_σ1 ∘ … ∘ g_σK(c), c the fixed point of g_σK — the
// colouring orbit of the pixel's winning point, run in lockstep with it (paper §4), to within
// s_G^K. CV_32FC2 (u, v), v = 1 − y.
cv::Mat uv_of_whole_keys(const ifsfx::detail::AddressRaster& tops, const Ifs& G, int threads) {
  const auto n = static_cast<std::uint32_t>(G.size());
  const int K = tops.symbols();
  cv::Mat uv(tops.viewport.size, CV_32FC2, cv::Scalar::all(0));
  parallel_for(static_cast<std::size_t>(uv.rows), threads, [&](std::size_t r, int) {
    const int row = static_cast<int>(r);
    auto* out = uv.ptr<cv::Vec2f>(row);
    for (int col = 0; col < uv.cols; ++col) {
      const std::uint64_t key = tops.at(col, row);
      if (key == 0) continue;
      const auto symbol = [&](int m) { return std::min(tops.symbol(key, m), n - 1); };
      Point y = ifsfx::detail::fixed_point(G.maps[symbol(K - 1)]);
      for (int m = K - 1; m >= 0; --m) y = G.maps[symbol(m)](y);
      out[col] = cv::Vec2f(static_cast<float>(y.x), static_cast<float>(1 - y.y));
    }
  });
  return uv;
}

}  // namespace

void check_flame_chaos(const Sampling& sampling, bool exact) {
  if (exact)
    throw Error(ErrorKind::invalid_argument,
                "exact: the exact descent follows inverse maps, and a flame's xforms have none; "
                "its tops and steal maps come from the chaos game (got a flame)");
  if (sampling.seamless)
    throw Error(ErrorKind::invalid_argument,
                "seamless: a flame is drawn in its own plane, not on the torus of a tile (got a "
                "flame)");
}

Viewport flame_viewport(const Flame& flame, cv::Size size, const Sampling& sampling) {
  if (sampling.view) return {*sampling.view, size, false};
  const Camera camera = sized_camera(flame, size);
  const double ppu = camera.scale * std::exp2(camera.zoom);
  const double half_w = 0.5 * size.width / ppu, half_h = 0.5 * size.height / ppu;
  // The flame plane's rows [cy − h, cy + h] downwards are the IFS plane's [−cy − h, −cy + h].
  return {{camera.center.x - half_w, -camera.center.y - half_h, camera.center.x + half_w,
           -camera.center.y + half_h},
          size,
          false};
}

std::optional<Ifs> affine_ifs(const Flame& flame) {
  if (flame.final_xform || flame.xforms.empty()) return std::nullopt;
  Ifs ifs;
  ifs.name = flame.name;
  for (const Xform& xf : flame.xforms) {
    // One linear term of weight 1 (an xform without variations is the constant map to the
    // origin, not its affine map: flame/xform_eval.cpp).
    const bool plain = xf.variations.size() == 1 &&
                       variation(xf.variations[0].id).name == "linear" &&
                       xf.variations[0].weight == 1;
    const bool xaos =
        std::any_of(xf.chaos.begin(), xf.chaos.end(), [](double c) { return c != 1; });
    if (!plain || xf.post || !xf.pre_variations.empty() || !xf.post_variations.empty() || xaos)
      return std::nullopt;
    const AffineMap& A = xf.pre;
    ifs.maps.push_back({A.a, -A.b, -A.c, A.d, A.e, -A.f});  // S∘A∘S
    // Unnormalised: effective_probabilities divides by their sum as xform_pickers(flame, true)
    // does.
    ifs.probabilities.push_back(xf.weight);
  }
  return ifs;
}

cv::Mat flame_attractor(const Flame& flame, cv::Size size, const Sampling& sampling,
                        RenderStats* stats) {
  check_inputs(flame, size, sampling, false);
  const auto start = std::chrono::steady_clock::now();
  const Plan plan = plan_of(flame, size, sampling);
  const Walk walk(flame, plan, plan.affine ? default_burn_in(*plan.affine) : kFlameBurnIn);
  const auto points =
      static_cast<std::uint64_t>(std::ceil(sampling.quality * size.width * double(size.height)));
  const std::uint64_t chunks = ifsfx::detail::chunk_count(points, chunk_points(plan));
  const int workers = worker_count(chunks, sampling.threads);
  std::vector<cv::Mat> hits(static_cast<std::size_t>(workers));
  parallel_for(chunks, workers, [&](std::size_t chunk, int worker) {
    sampling.cancel.check("render");
    cv::Mat& mask = hits[static_cast<std::size_t>(worker)];
    if (mask.empty()) mask = cv::Mat::zeros(size, CV_8UC1);
    walk.walk(sampling.seed, chunk, ifsfx::detail::chunk_size(points, chunk, chunk_points(plan)),
              [&mask](long pixel, std::uint64_t) { mask.data[pixel] = 255; });
  });
  cv::Mat out = cv::Mat::zeros(size, CV_8UC1);
  for (const cv::Mat& mask : hits)
    if (!mask.empty()) cv::bitwise_or(out, mask, out);
  if (stats)
    *stats = {points - walk.given_up(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              cv::countNonZero(out) / static_cast<double>(size.area()), plan.viewport.view};
  return out;
}

TopSymbols flame_top_symbols(const Flame& flame, cv::Size size, const TopsOptions& options) {
  check_inputs(flame, size, options.sampling, options.exact);
  const Plan plan = plan_of(flame, size, options.sampling);
  ifsfx::detail::ChaosTopsStats chaos;
  // 32-bit keys: 32/b ≥ 2 symbols, as top_symbols keeps them.
  TopSymbols out = ifsfx::detail::symbols_of(flame_keys(flame, plan, options.sampling, 32, &chaos));
  out.points = chaos.points;
  return out;
}

cv::Mat flame_tops(const Flame& flame, cv::Size size, const TopsOptions& options,
                   const Rgb& background, bool alpha, TopsPictureStats* stats) {
  const TopSymbols tops = flame_top_symbols(flame, size, options);
  std::vector<Rgb> colours;
  for (std::size_t n = 0; n < flame.xforms.size(); ++n)
    colours.push_back(palette_colour(n, flame.xforms.size()));
  if (stats) *stats = {.view = tops.view, .points = tops.points};
  return tops_picture(render_tops(tops, colours, options.second_symbol), background, alpha, stats);
}

StealMap flame_steal_map(const Flame& flame, const Ifs& G, cv::Size size,
                         const StealMapOptions& options, StealMapStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  check_inputs(flame, size, options.sampling, options.exact);
  ifsfx::detail::check_chaos_game(
      {.ifs = G, .name = G.name.empty() ? "colouring IFS" : G.name, .contracting = true});
  if (G.size() != flame.xforms.size())
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("colouring IFS: must have one map per xform of the flame (got {} for "
                            "{})",
                            G.size(), flame.xforms.size()));
  const Plan plan = plan_of(flame, size, options.sampling);
  // compute_steal_map's record size: 32 bits when their 32/b symbols pin T to 1/8192 through G.
  const int bits = ifsfx::detail::symbol_bits(G.size());
  const bool short_keys = std::pow(ifsfx::detail::word_contraction(G), 32 / bits) * 8192 <= 1;
  ifsfx::detail::ChaosTopsStats chaos;
  const ifsfx::detail::AddressRaster tops =
      flame_keys(flame, plan, options.sampling, short_keys ? 32 : 64, &chaos);
  options.sampling.cancel.check("steal map");
  StealMap map;
  map.source_uv = plan.affine
                      ? ifsfx::detail::uv_from_keys(tops, *plan.affine, G, options.sampling.threads)
                      : uv_of_whole_keys(tops, G, options.sampling.threads);
  map.coverage = tops.coverage();
  if (stats) {
    const double area = static_cast<double>(size.area());
    *stats = {
        .points = chaos.points,
        .rounds = chaos.rounds,
        .hit = static_cast<double>(chaos.hit) / area,
        .propagated = chaos.propagated,
        .filled = chaos.filled,
        .coverage = cv::countNonZero(map.coverage) / area,
        .levels = tops.symbols(),
        .seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        .view = plan.viewport.view};
  }
  return map;
}

}  // namespace ifsfx::flame
