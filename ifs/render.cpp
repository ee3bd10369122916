// SPDX-License-Identifier: Apache-2.0
#include "ifs/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <new>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/preconditions.h"
#include "ifs/detail/walkers.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx {
namespace {

// Runs `points` chaos-game points of `walk` over fixed chunks, on the kernels of this CPU's level
// (ifs/cpu.h); `make_state()` gives each worker its state, and state.run(kernels, spec, seeds, n)
// runs one chunk of n points into it.
template <class State, class MakeState>
std::vector<State> scatter(const detail::WalkTables& walk, std::uint64_t points,
                           const ChaosGameOptions& options, MakeState&& make_state) {
  const detail::WalkKernels& kernels = detail::walk_kernels();
  const std::uint64_t chunks = detail::chunk_count(points);
  const int workers = worker_count(chunks, options.threads);
  std::vector<State> states;
  states.reserve(static_cast<std::size_t>(workers));
  for (int w = 0; w < workers; ++w) states.push_back(make_state());
  parallel_for(chunks, workers, [&](std::size_t chunk, int worker) {
    options.cancel.check("render");
    states[static_cast<std::size_t>(worker)].run(kernels, walk.spec(),
                                                 detail::lane_seeds(options.seed, chunk),
                                                 detail::chunk_size(points, chunk));
  });
  return states;
}

int burn_in_of(const Ifs& ifs, const ChaosGameOptions& options) {
  return options.burn_in > 0 ? options.burn_in : default_burn_in(ifs);
}

// The chaos-game family's checks (detail::check_chaos_game), then the renderers' own options.
void check_render_inputs(const Ifs& ifs, cv::Size size, const RenderOptions& options) {
  detail::check_chaos_game({.ifs = ifs, .size = size, .sampling = &options.sampling});
  if (options.supersample < 1 || options.supersample > 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("supersample: must be 1 to 16 (got {})", options.supersample));
  check_size(size * options.supersample, "size × supersample");
  if (!(options.gamma > 0) || !std::isfinite(options.gamma))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("gamma: must be positive (got {})", options.gamma));
  if (!(options.brightness > 0) || !std::isfinite(options.brightness))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("brightness: must be positive (got {})", options.brightness));
}

std::uint64_t point_budget(cv::Size size, double quality) {
  return static_cast<std::uint64_t>(
      std::ceil(quality * size.width * static_cast<double>(size.height)));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Per-worker hit mask: the attractor as a set needs one byte store per point, no read.
struct HitState {
  cv::Mat hits;
  explicit HitState(const Viewport& v) : hits(cv::Mat::zeros(v.size, CV_8UC1)) {}
  void run(const detail::WalkKernels& k, const detail::WalkSpec& w, const detail::LaneSeeds& seeds,
           std::uint64_t points) {
    k.hits(w, seeds, points, hits.data);
  }
};

// Per-worker visit counts.
struct CountState {
  cv::Mat counts;
  explicit CountState(const Viewport& v) : counts(cv::Mat::zeros(v.size, CV_32SC1)) {}
  void run(const detail::WalkKernels& k, const detail::WalkSpec& w, const detail::LaneSeeds& seeds,
           std::uint64_t points) {
    k.counts(w, seeds, points, reinterpret_cast<std::uint32_t*>(counts.data));
  }
};

// Visit count and palette-coordinate sum per pixel, packed in one 32-bit word so a point costs a
// single memory update (detail::MeasureCells), folded into the shared totals at the end, and
// every kFoldPoints points so that the spills always have room.
class MeasureState {
 public:
  static constexpr std::uint64_t kFoldPoints = std::uint64_t{1} << 28;

  // The wide totals of every worker's cells, zeroed by calloc: an allocation this large comes
  // fresh from the system, already zero, so only the pages a fold writes cost anything (a
  // vector cleared all 32 MiB of a 1080p raster first, 20 ms).
  struct Totals {
    explicit Totals(std::size_t area)
        : count(static_cast<std::uint64_t*>(std::calloc(area, sizeof(std::uint64_t)))),
          colour(static_cast<std::uint64_t*>(std::calloc(area, sizeof(std::uint64_t)))) {
      if (!count || !colour) throw std::bad_alloc();
    }
    struct Free {
      void operator()(std::uint64_t* p) const { std::free(p); }
    };
    std::unique_ptr<std::uint64_t[], Free> count, colour;
    std::mutex mutex;
  };

  MeasureState(const Viewport& v, Totals& totals)
      : cells_(static_cast<std::size_t>(v.size.area()), 0),
        spills_(kFoldPoints / detail::MeasureCells::kFull),
        totals_(&totals) {}
  MeasureState(MeasureState&&) = default;

  void run(const detail::WalkKernels& k, const detail::WalkSpec& w, const detail::LaneSeeds& seeds,
           std::uint64_t points) {
    if (pending_ + points > kFoldPoints) fold();
    pending_ += points;
    detail::MeasureCells cells{cells_.data(), spills_.data(), spilled_};
    k.measure(w, seeds, points, cells);
    spilled_ = cells.spilled;
  }
  void fold() {
    if (pending_ == 0) return;  // nothing ran here since the last fold
    detail::MeasureCells cells{cells_.data(), spills_.data(), spilled_};
    std::lock_guard lock(totals_->mutex);
    detail::fold_measure_cells(cells, cells_.size(), totals_->count.get(), totals_->colour.get());
    spilled_ = 0;
    pending_ = 0;
  }

 private:
  std::vector<std::uint32_t> cells_;
  std::vector<std::uint64_t> spills_;
  std::uint64_t spilled_ = 0;
  Totals* totals_;
  std::uint64_t pending_ = 0;
};

// Palette used when an IFS has no colours: a perceptually ordered ramp (dark violet, magenta,
// orange, pale yellow), sampled linearly.
Rgb ramp(double t) {
  static constexpr std::array<Rgb, 5> kStops = {Rgb{0.23, 0.05, 0.45}, Rgb{0.55, 0.10, 0.55},
                                                Rgb{0.90, 0.30, 0.35}, Rgb{0.98, 0.62, 0.20},
                                                Rgb{0.99, 0.93, 0.60}};
  t = std::clamp(t, 0.0, 1.0) * (kStops.size() - 1);
  const auto i = std::min<std::size_t>(static_cast<std::size_t>(t), kStops.size() - 2);
  const double w = t - static_cast<double>(i);
  const Rgb& p = kStops[i];
  const Rgb& q = kStops[i + 1];
  return {p.r + w * (q.r - p.r), p.g + w * (q.g - p.g), p.b + w * (q.b - p.b)};
}

// The colour at palette coordinate t ∈ [0,1]: through the IFS's own colours (map n at n/(N−1))
// when it has them, else the default ramp.
Rgb palette_at(const Ifs& ifs, double t) {
  if (ifs.colours.empty()) return ramp(t);
  if (ifs.colours.size() == 1) return ifs.colours[0];
  const double pos = std::clamp(t, 0.0, 1.0) * static_cast<double>(ifs.colours.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(pos), ifs.colours.size() - 2);
  const double w = pos - static_cast<double>(i);
  const Rgb& p = ifs.colours[i];
  const Rgb& q = ifs.colours[i + 1];
  return {p.r + w * (q.r - p.r), p.g + w * (q.g - p.g), p.b + w * (q.b - p.b)};
}

double coverage_of(const cv::Mat& mask) {
  return static_cast<double>(cv::countNonZero(mask)) / static_cast<double>(mask.total());
}

// Of a BGR float image (channels ≥ 0): the share of pixels that are not black, in one pass (a
// grey conversion, a threshold and a count took three, as long as the tone map itself).
double coverage_of_colour(const cv::Mat& image) {
  std::size_t lit = 0;
  for (int r = 0; r < image.rows; ++r) {
    const auto* row = image.ptr<cv::Vec3f>(r);
    for (int c = 0; c < image.cols; ++c) lit += row[c][0] > 0 || row[c][1] > 0 || row[c][2] > 0;
  }
  return static_cast<double>(lit) / static_cast<double>(image.total());
}

}  // namespace

Rgb palette_colour(std::size_t n, std::size_t count) {
  return ramp(count <= 1 ? 0.0 : static_cast<double>(n) / static_cast<double>(count - 1));
}

Rgb palette_ramp(double t) {
  return ramp(t);
}

cv::Mat visit_counts(const Ifs& ifs, const Viewport& viewport, std::uint64_t points,
                     const ChaosGameOptions& options) {
  detail::check_chaos_game({.ifs = ifs,
                            .threads = options.threads,
                            .burn_in = options.burn_in,
                            .size = viewport.size,
                            .view = viewport.view});
  const detail::WalkTables walk(ifs, viewport, burn_in_of(ifs, options));
  auto states = scatter<CountState>(walk, points, options, [&] { return CountState(viewport); });
  cv::Mat total = states[0].counts;
  for (std::size_t w = 1; w < states.size(); ++w) total += states[w].counts;
  return total;
}

cv::Mat render_attractor(const Ifs& ifs, cv::Size size, const RenderOptions& options,
                         RenderStats* stats) {
  check_render_inputs(ifs, size, options);
  const Viewport viewport = framed_viewport(ifs, size, options.sampling);
  const std::uint64_t points = point_budget(size, options.sampling.quality);
  const auto start = std::chrono::steady_clock::now();
  const ChaosGameOptions chaos{.seed = options.sampling.seed,
                               .threads = options.sampling.threads,
                               .cancel = options.sampling.cancel};
  const detail::WalkTables walk(ifs, viewport, burn_in_of(ifs, chaos));
  auto states = scatter<HitState>(walk, points, chaos, [&] { return HitState(viewport); });
  cv::Mat mask = states[0].hits;
  for (std::size_t w = 1; w < states.size(); ++w) cv::bitwise_or(mask, states[w].hits, mask);
  if (stats) *stats = {points, seconds_since(start), coverage_of(mask), viewport.view};
  return mask;
}

cv::Mat render_measure(const Ifs& ifs, cv::Size size, const RenderOptions& options,
                       RenderStats* stats) {
  check_render_inputs(ifs, size, options);
  const int k = options.supersample;
  const Viewport viewport{framed_viewport(ifs, size, options.sampling).view, size * k};
  const std::uint64_t points = point_budget(size, options.sampling.quality);

  const auto area = static_cast<std::size_t>(viewport.size.area());
  MeasureState::Totals totals(area);

  const auto start = std::chrono::steady_clock::now();
  const ChaosGameOptions chaos{.seed = options.sampling.seed,
                               .threads = options.sampling.threads,
                               .cancel = options.sampling.cancel};
  const detail::WalkTables walk(ifs, viewport, burn_in_of(ifs, chaos));
  auto states =
      scatter<MeasureState>(walk, points, chaos, [&] { return MeasureState(viewport, totals); });
  for (auto& s : states) s.fold();
  const double seconds = seconds_since(start);

  // Log-density tone map v = log(1 + k·c) / log(1 + k·max), k = brightness / mean covered count
  // (so the look does not depend on --quality), then the display gamma.
  std::uint64_t max_count = 0, sum = 0, covered = 0;
  for (std::size_t i = 0; i < area; ++i) {
    const std::uint64_t c = totals.count[i];
    max_count = std::max(max_count, c);
    sum += c;
    covered += c > 0;
  }
  // Every pixel is written below (uncovered ones 0), so the raster is not cleared first.
  cv::Mat hires(viewport.size, CV_32FC3);
  if (covered == 0) {
    hires.setTo(cv::Scalar::all(0));
  } else {
    const double kk = options.brightness * static_cast<double>(covered) / static_cast<double>(sum);
    const double norm = std::log1p(kk * static_cast<double>(max_count));
    const auto tone = [&](std::uint64_t c) {
      return std::pow(std::log1p(kk * static_cast<double>(c)) / norm, 1.0 / options.gamma);
    };
    // v is a function of the count alone, and counts repeat (a few thousand distinct values
    // cover a 1080p fern): each count below kToneCounts is toned once, then looked up (the same
    // expression, so the same bits). -1: not toned yet (v ≥ 0).
    constexpr std::uint64_t kToneCounts = std::uint64_t{1} << 16;
    std::vector<double> toned(std::min(max_count + 1, kToneCounts), -1.0);
    auto* out = hires.ptr<cv::Vec3f>();
    for (std::size_t i = 0; i < area; ++i) {
      const auto c = totals.count[i];
      if (c == 0) {
        out[i] = cv::Vec3f(0, 0, 0);
        continue;
      }
      double v;
      if (c < toned.size()) {
        if (toned[c] < 0) toned[c] = tone(c);
        v = toned[c];
      } else {
        v = tone(c);
      }
      const double t = static_cast<double>(totals.colour[i]) / (63.0 * static_cast<double>(c));
      const Rgb rgb = palette_at(ifs, t);
      out[i] = cv::Vec3f(static_cast<float>(rgb.b * v), static_cast<float>(rgb.g * v),
                         static_cast<float>(rgb.r * v));
    }
  }
  cv::Mat image;
  if (k == 1)
    image = hires;
  else
    cv::resize(hires, image, size, 0, 0, cv::INTER_AREA);  // box filter: the mean of k×k cells
  if (stats) *stats = {points, seconds, coverage_of_colour(image), viewport.view};
  return image;
}

}  // namespace ifsfx
