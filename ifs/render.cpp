#include "ifs/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/walkers.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx {
namespace {

// Runs `points` chaos-game points over fixed chunks; `make_worker(worker)` gives each worker its
// per-thread state, and state.plot(lane, pixel, map) plots one point that lands on `viewport`.
template <class State, class MakeState>
std::vector<State> scatter(const Ifs& ifs, const Viewport& viewport, std::uint64_t points,
                           const ChaosGameOptions& options, MakeState&& make_state) {
  const detail::PixelMapping mapping = detail::pixel_mapping(viewport);
  const detail::MapTable maps(ifs);
  const MapPicker pick(effective_probabilities(ifs));
  const int burn_in = options.burn_in > 0 ? options.burn_in : default_burn_in(ifs);
  const std::uint64_t chunks = detail::chunk_count(points);
  const int workers = worker_count(chunks, options.threads);
  std::vector<State> states;
  states.reserve(static_cast<std::size_t>(workers));
  for (int w = 0; w < workers; ++w) states.push_back(make_state());
  parallel_for(chunks, workers, [&](std::size_t chunk, int worker) {
    options.cancel.check("render");
    State& state = states[static_cast<std::size_t>(worker)];
    const std::uint64_t n = detail::chunk_size(points, chunk);
    state.begin_chunk(n);
    detail::plot_chunk(
        maps, pick, mapping, options.seed, chunk, n, burn_in,
        [&](int lane, long pixel, std::uint32_t map) { state.plot(lane, pixel, map); });
  });
  return states;
}

void check_render_inputs(const Ifs& ifs, cv::Size size, const RenderOptions& options) {
  check_size(size);
  if (ifs.maps.empty()) throw Error(ErrorKind::invalid_ifs, "ifs: needs at least one map (got 0)");
  if (options.supersample < 1 || options.supersample > 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--supersample: must be 1 to 16 (got {})", options.supersample));
  check_size(size * options.supersample, "--size × --supersample");
  if (!(options.quality > 0 && options.quality <= kMaxQuality))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("--quality: must be a positive number of points per pixel, at most {:g} "
                    "(got {})",
                    kMaxQuality, options.quality));
  if (!(options.gamma > 0) || !std::isfinite(options.gamma))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--gamma: must be positive (got {})", options.gamma));
  if (!(options.brightness > 0) || !std::isfinite(options.brightness))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("brightness: must be positive (got {})", options.brightness));
}

Viewport viewport_for(const Ifs& ifs, cv::Size size, const RenderOptions& options) {
  const Box view = options.view ? *options.view
                                : fit_view(attractor_bounds(ifs, options.seed, options.cancel),
                                           size, options.margin);
  return {view, size};
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
  void begin_chunk(std::uint64_t) {}
  void plot(int, long pixel, std::uint32_t) { hits.data[pixel] = 255; }
};

// Per-worker visit counts.
struct CountState {
  cv::Mat counts;
  explicit CountState(const Viewport& v) : counts(cv::Mat::zeros(v.size, CV_32SC1)) {}
  void begin_chunk(std::uint64_t) {}
  void plot(int, long pixel, std::uint32_t) {
    ++reinterpret_cast<std::uint32_t*>(counts.data)[pixel];
  }
};

// Visit count and palette-coordinate sum per pixel, packed in one 64-bit word so a point costs a
// single memory update: count in the low 32 bits, Σc in the high 32 with c quantised to 6 bits.
// Σc ≤ 63 · points, so folding into wide totals every 2^26 points keeps both halves exact.
//
// A 1080p raster of such words is 16 MiB, and points land on it at random: updated directly,
// nearly every point is a cache miss. So points are first binned by tile (2^14 consecutive
// cells, 128 KiB: a slice of the image that fits in L2) into short queues, and a full queue is
// applied to its tile in one burst while that tile is in cache.
class MeasureState {
 public:
  static constexpr std::uint64_t kFoldPoints = std::uint64_t{1} << 26;
  static constexpr int kPaletteBits = 6;
  static constexpr int kTileBits = 14;
  static constexpr std::uint32_t kTileMask = (1u << kTileBits) - 1;
  static constexpr std::uint32_t kQueueLength = 256;

  struct Totals {
    std::vector<std::uint64_t> count, colour;
    std::mutex mutex;
  };

  MeasureState(const Viewport& v, const std::vector<std::uint32_t>& map_colours, Totals& totals)
      : cells_(static_cast<std::size_t>(v.size.area()), 0),
        tiles_((cells_.size() + kTileMask) >> kTileBits),
        queue_(tiles_ * kQueueLength),
        queued_(tiles_, 0),
        map_colour_(map_colours),
        totals_(&totals) {
    palette_.fill(0);
  }
  MeasureState(MeasureState&&) = default;

  void begin_chunk(std::uint64_t points) {
    if (pending_ + points > kFoldPoints) fold();
    pending_ += points;
  }
  void plot(int lane, long pixel, std::uint32_t map) {
    // c_k = (c_{k-1} + c_σk) / 2 in 16-bit fixed point (DESIGN.md §4). Off-raster points do not
    // reach here, so the palette coordinate skips them: it is a local colour, not an address.
    std::uint32_t& c = palette_[static_cast<std::size_t>(lane)];
    c = (c + map_colour_[map]) >> 1;
    const std::uint32_t c6 =
        std::min<std::uint32_t>((c + (1u << (15 - kPaletteBits))) >> (16 - kPaletteBits), 63);
    const auto cell = static_cast<std::uint32_t>(pixel);
    const std::uint32_t tile = cell >> kTileBits;
    std::uint32_t& length = queued_[tile];
    queue_[tile * kQueueLength + length] = (c6 << kTileBits) | (cell & kTileMask);
    if (++length == kQueueLength) drain(tile);
  }
  void fold() {
    for (std::uint32_t tile = 0; tile < tiles_; ++tile) drain(tile);
    std::lock_guard lock(totals_->mutex);
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      if (cells_[i] == 0) continue;
      totals_->count[i] += cells_[i] & 0xffffffffu;
      totals_->colour[i] += cells_[i] >> 32;
      cells_[i] = 0;
    }
    pending_ = 0;
  }

 private:
  void drain(std::uint32_t tile) {
    std::uint64_t* cells = cells_.data() + (static_cast<std::size_t>(tile) << kTileBits);
    const std::uint32_t* entry = queue_.data() + tile * kQueueLength;
    for (std::uint32_t k = 0, n = queued_[tile]; k < n; ++k)
      cells[entry[k] & kTileMask] += (static_cast<std::uint64_t>(entry[k] >> kTileBits) << 32) | 1;
    queued_[tile] = 0;
  }

  std::vector<std::uint64_t> cells_;
  std::uint32_t tiles_;
  std::vector<std::uint32_t> queue_;  // per tile: kQueueLength entries of (c6 << 14 | cell in tile)
  std::vector<std::uint32_t> queued_;      // entries waiting per tile
  std::vector<std::uint32_t> map_colour_;  // c_n of each map, 16-bit fixed point
  std::array<std::uint32_t, detail::kLanes> palette_;
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

}  // namespace

Rgb palette_colour(std::size_t n, std::size_t count) {
  return ramp(count <= 1 ? 0.0 : static_cast<double>(n) / static_cast<double>(count - 1));
}

Rgb palette_ramp(double t) {
  return ramp(t);
}

cv::Mat visit_counts(const Ifs& ifs, const Viewport& viewport, std::uint64_t points,
                     const ChaosGameOptions& options) {
  check_size(viewport.size);
  auto states =
      scatter<CountState>(ifs, viewport, points, options, [&] { return CountState(viewport); });
  cv::Mat total = states[0].counts;
  for (std::size_t w = 1; w < states.size(); ++w) total += states[w].counts;
  return total;
}

cv::Mat render_attractor(const Ifs& ifs, cv::Size size, const RenderOptions& options,
                         RenderStats* stats) {
  check_render_inputs(ifs, size, options);
  const Viewport viewport = viewport_for(ifs, size, options);
  const std::uint64_t points = point_budget(size, options.quality);
  const auto start = std::chrono::steady_clock::now();
  auto states = scatter<HitState>(
      ifs, viewport, points,
      {.seed = options.seed, .threads = options.threads, .cancel = options.cancel},
      [&] { return HitState(viewport); });
  cv::Mat mask = states[0].hits;
  for (std::size_t w = 1; w < states.size(); ++w) cv::bitwise_or(mask, states[w].hits, mask);
  if (stats) *stats = {points, seconds_since(start), coverage_of(mask), viewport.view};
  return mask;
}

cv::Mat render_measure(const Ifs& ifs, cv::Size size, const RenderOptions& options,
                       RenderStats* stats) {
  check_render_inputs(ifs, size, options);
  const int k = options.supersample;
  const Viewport viewport{viewport_for(ifs, size, options).view, size * k};
  const std::uint64_t points = point_budget(size, options.quality);

  std::vector<std::uint32_t> map_colour(ifs.size());
  for (std::size_t n = 0; n < ifs.size(); ++n)
    map_colour[n] =
        ifs.size() <= 1
            ? 0
            : static_cast<std::uint32_t>(std::lround(65535.0 * static_cast<double>(n) /
                                                     static_cast<double>(ifs.size() - 1)));
  MeasureState::Totals totals;
  const auto area = static_cast<std::size_t>(viewport.size.area());
  totals.count.assign(area, 0);
  totals.colour.assign(area, 0);

  const auto start = std::chrono::steady_clock::now();
  auto states = scatter<MeasureState>(
      ifs, viewport, points,
      {.seed = options.seed, .threads = options.threads, .cancel = options.cancel},
      [&] { return MeasureState(viewport, map_colour, totals); });
  for (auto& s : states) s.fold();
  const double seconds = seconds_since(start);

  // Log-density tone map v = log(1 + k·c) / log(1 + k·max), k = brightness / mean covered count
  // (so the look does not depend on --quality), then the display gamma.
  std::uint64_t max_count = 0, sum = 0, covered = 0;
  for (auto c : totals.count) {
    max_count = std::max(max_count, c);
    sum += c;
    covered += c > 0;
  }
  cv::Mat hires(viewport.size, CV_32FC3, cv::Scalar::all(0));
  if (covered > 0) {
    const double kk = options.brightness * static_cast<double>(covered) / static_cast<double>(sum);
    const double norm = std::log1p(kk * static_cast<double>(max_count));
    auto* out = hires.ptr<cv::Vec3f>();
    for (std::size_t i = 0; i < area; ++i) {
      const auto c = totals.count[i];
      if (c == 0) continue;
      const double v =
          std::pow(std::log1p(kk * static_cast<double>(c)) / norm, 1.0 / options.gamma);
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
  if (stats) {
    cv::Mat grey;
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    *stats = {points, seconds, coverage_of(grey > 0), viewport.view};
  }
  return image;
}

}  // namespace ifsfx
