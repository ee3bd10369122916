// SPDX-License-Identifier: Apache-2.0
#include "superifs/texture.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/render.h"

namespace ifsfx {

namespace {

constexpr int band_rows = 16;  // rows per chunk of work, fixed (never from the thread count)

// Symbols of the top address that set a pixel's tops colour: M^-6 is below 8-bit resolution.
constexpr int top_symbols = 6;

// One level of the descent: which IFS and which map took the point one step back.
struct Symbol {
  std::uint32_t n = 0, m = 0;
};

// Whether some set pixel of `mask` lies within `r` pixels (Chebyshev) of the point (x, y).
bool near(const BitMask& mask, double x, double y, int r) {
  if (!(x > -r - 1 && y > -r - 1 && x < mask.width() + r + 1 && y < mask.height() + r + 1))
    return false;
  const int c = static_cast<int>(std::floor(x)), row = static_cast<int>(std::floor(y));
  for (int j = std::max(0, row - r); j <= std::min(mask.height() - 1, row + r); ++j)
    for (int i = std::max(0, c - r); i <= std::min(mask.width() - 1, c + r); ++i)
      if (mask.test(i, j)) return true;
  return false;
}

// `near` on the torus of the tile: the square around (x, y) wraps around the mask's edges.
bool near_wrapped(const BitMask& mask, double x, double y, int r) {
  const int w = mask.width(), h = mask.height();
  const int c = static_cast<int>(std::floor(x)), row = static_cast<int>(std::floor(y));
  const int rx = std::min(r, (w - 1) / 2), ry = std::min(r, (h - 1) / 2);
  for (int j = row - ry; j <= row + ry; ++j)
    for (int i = c - rx; i <= c + rx; ++i)
      if (mask.test(((i % w) + w) % w, ((j % h) + h) % h)) return true;
  return false;
}

// What the descent reads, flattened once per render: for each (n, m) the inverse map in pixel
// coordinates and the box its piece lies in; for each level of history, newest first, the choices
// and the masks one step back.
struct Descent {
  struct Piece {
    AffineMap inverse;
    Box bounds;
  };
  struct Level {
    const std::uint32_t* ifs;     // n_v
    const std::uint32_t* source;  // v_m at [v · M + m]
    const BitMask* previous;      // the V masks one step back
  };
  std::vector<Piece> pieces;  // [n · M + m]
  std::vector<Level> levels;
  std::size_t maps = 0;
  int reach = 0;  // how far a preimage that just misses every mask is looked for
  bool torus = false;
  double width = 0, height = 0;  // of the raster

  explicit Descent(const Buffers& buffers)
      : maps(buffers.super().maps()),
        torus(buffers.seamless()),
        width(buffers.size().width),
        height(buffers.size().height) {
    for (std::size_t n = 0; n < buffers.super().size(); ++n)
      for (std::size_t m = 0; m < maps; ++m)
        pieces.push_back({buffers.pixel_inverse(n, m), buffers.piece_bounds(n, m)});
    const auto& history = buffers.history();
    for (std::size_t level = history.size(); level-- > 0;)
      levels.push_back({history[level].choices.ifs.data(), history[level].choices.source.data(),
                        history[level].previous.data()});
    // A preimage that lands just off every conservative mask (x is exact, the masks are not) is
    // looked for a little further before the descent gives up at that level.
    reach = buffers.dilation() + 1;
  }

  // A candidate of the descent on the torus: a point of a buffer, and the candidate one level
  // up it came from (-1 at the pixel), with the symbol that took it there.
  struct Candidate {
    Point z;
    std::size_t buf;
    int parent;
    Symbol symbol;
  };
  static constexpr std::size_t kMaxCandidates = 8;
  // The candidates of every level, reused from pixel to pixel by one thread.
  using Trail = std::vector<std::vector<Candidate>>;

  // The descent on the torus of the tile (docs/design.md §11): the point z of a buffer has a
  // preimage under wrap ∘ f^n_m for every translate z + λ by the lattice (λ = (i·W, j·H) pixels)
  // in the piece's box whose preimage lies in the tile and on the source buffer. The top address
  // keeps the largest of all (eq. 7, eq. 14's Top): the descent follows every candidate whose
  // symbols agree so far (at most kMaxCandidates, in a fixed order), taking at each level the
  // highest m that any has; the word and point are those of the first candidate at the end.
  std::size_t run_torus(std::size_t v, int col, int row, std::vector<Symbol>& word, Point& z,
                        Trail& trail) const {
    trail.resize(levels.size() + 1);
    trail[0].assign(1, Candidate{{col + 0.5, row + 0.5}, v, -1, {}});
    std::size_t depth = 0;
    for (const Level& level : levels) {
      const std::vector<Candidate>& now = trail[depth];
      std::vector<Candidate>& next = trail[depth + 1];
      next.clear();
      for (std::size_t m = maps; m-- > 0 && next.empty();) {
        for (std::size_t k = 0; k < now.size() && next.size() < kMaxCandidates; ++k) {
          const Candidate& c = now[k];
          const std::uint32_t n = level.ifs[c.buf];
          const Piece& piece = pieces[n * maps + m];
          const std::size_t to = level.source[c.buf * maps + m];
          for_translates(c.z, piece.bounds, [&](Point q) {
            const Point y = piece.inverse(q);
            if (in_tile(y) && level.previous[to].test(static_cast<int>(y.x), static_cast<int>(y.y)))
              next.push_back({y, to, static_cast<int>(k), {n, static_cast<std::uint32_t>(m)}});
            return next.size() < kMaxCandidates;
          });
        }
      }
      if (next.empty()) {
        // A preimage just off every conservative mask: looked for a little further.
        const Candidate& c = now[0];
        const std::uint32_t n = level.ifs[c.buf];
        for (std::size_t m = maps; m-- > 0 && next.empty();) {
          const Piece& piece = pieces[n * maps + m];
          const std::size_t to = level.source[c.buf * maps + m];
          for_translates(c.z, piece.bounds, [&](Point q) {
            const Point y = piece.inverse(q);
            if (!in_tile(y) || !near_wrapped(level.previous[to], y.x, y.y, reach)) return true;
            next.push_back({y, to, 0, {n, static_cast<std::uint32_t>(m)}});
            return false;
          });
        }
      }
      if (next.empty()) break;
      ++depth;
    }
    // The word of the first candidate, read back up the trail.
    int k = 0;
    z = trail[depth][0].z;
    for (std::size_t d = depth; d > 0; --d) {
      const Candidate& c = trail[d][static_cast<std::size_t>(k)];
      word[d - 1] = c.symbol;
      k = c.parent;
    }
    return depth;
  }

  // Whether a point lies in the tile, half-open: on the torus each point has one representative
  // in [0, W) × [0, H), so a preimage on the tile's far edge is its translate on the near one.
  bool in_tile(Point y) const { return y.x >= 0 && y.x < width && y.y >= 0 && y.y < height; }

  // Calls visit(z + λ) for the translates of z by the lattice of the tile that lie in `box`, i then
  // j increasing, until visit returns false.
  template <class Visit>
  void for_translates(Point z, const Box& box, Visit&& visit) const {
    const double i0 = std::ceil((box.x0 - z.x) / width), i1 = std::floor((box.x1 - z.x) / width);
    const double j0 = std::ceil((box.y0 - z.y) / height), j1 = std::floor((box.y1 - z.y) / height);
    for (double i = i0; i <= i1; ++i)
      for (double j = j0; j <= j1; ++j)
        if (!visit(Point{z.x + i * width, z.y + j * height})) return;
  }

  // The exact descent (docs/design.md §3, §5) from the centre of pixel (col, row) of buffer v
  // through every level, newest first. Writes the symbols, returns how many, and leaves in `z` the
  // point reached (continuous pixel coordinates of the oldest level's buffers).
  std::size_t run(std::size_t v, int col, int row, std::vector<Symbol>& word, Point& z,
                  Trail& trail) const {
    if (torus) return run_torus(v, col, row, word, z, trail);
    z = {col + 0.5, row + 0.5};
    std::size_t depth = 0, buf = v;
    for (const Level& level : levels) {
      const std::uint32_t n = level.ifs[buf];
      const Piece* piece = &pieces[n * maps];
      const std::uint32_t* source = &level.source[buf * maps];
      // Top(…) of eq. 14: the highest m whose preimage lies in its source buffer one step back.
      std::size_t found = maps;
      Point y;
      for (std::size_t m = maps; m-- > 0;) {
        const Box& b = piece[m].bounds;
        if (!(z.x >= b.x0 && z.x <= b.x1 && z.y >= b.y0 && z.y <= b.y1)) continue;
        y = piece[m].inverse(z);
        if (level.previous[source[m]].test(y.x, y.y)) {
          found = m;
          break;
        }
      }
      if (found == maps) {
        for (std::size_t m = maps; m-- > 0;) {
          y = piece[m].inverse(z);
          if (near(level.previous[source[m]], y.x, y.y, reach)) {
            found = m;
            break;
          }
        }
      }
      if (found == maps) break;
      word[depth++] = {n, static_cast<std::uint32_t>(found)};
      z = y;
      buf = source[found];
    }
    return depth;
  }
};

void check_buffer(const Buffers& buffers, std::size_t v) {
  if (v >= buffers.count())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("buffer: must be 0..{} for count = {} (got {})", buffers.count() - 1,
                            buffers.count(), v));
}

void check_history(const Buffers& buffers, const char* what) {
  if (buffers.steps_done() > 0 && buffers.history().empty())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the buffers keep no history to descend through "
                            "(BufferOptions::history is 0)",
                            what));
}

// Tops colour: the top address read as a number in [0, 1), first symbol most significant, through
// a perceptual ramp, so that the pieces of the first level get distinct hues and their sub-pieces
// shades of them.
cv::Mat render_tops(const Buffers& buffers, std::size_t v) {
  check_history(buffers, "tops mode");
  const cv::Size size = buffers.size();
  const double m_count = static_cast<double>(buffers.super().maps());
  cv::Mat index(size, CV_8UC1, cv::Scalar(0));
  const cv::Mat& mask = buffers.mask(v);
  const Descent descent(buffers);
  const auto band = [&](cv::Range rows) {
    std::vector<Symbol> word(descent.levels.size());
    Descent::Trail trail;
    for (int row = rows.start; row < rows.end; ++row) {
      for (int col = 0; col < size.width; ++col) {
        if (!mask.at<std::uint8_t>(row, col)) continue;
        Point z;
        const std::size_t depth = descent.run(v, col, row, word, z, trail);
        double t = 0, scale = 1;
        for (std::size_t i = 0; i < std::min<std::size_t>(depth, top_symbols); ++i) {
          scale /= m_count;
          t += word[i].m * scale;
        }
        // 1..255 so that the ramp's darkest end still differs from the background.
        index.at<std::uint8_t>(row, col) = static_cast<std::uint8_t>(1 + std::floor(t * 254.999));
      }
    }
  };
  parallel_rows(size.height, band_rows, buffers.threads(), buffers.cancel(), "texture", band);
  cv::Mat colour;
  cv::applyColorMap(index, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar::all(0), mask == 0);
  return colour;
}

// Measure: brightness v = log(1 + k·ρ/mean) / log(1 + k·max/mean), then gamma, mean over the
// pixels that carry mass; hue the palette ramp at the pixel's mean palette coordinate, so the
// measure is coloured by map (docs/design.md §4).
cv::Mat render_measure(const Buffers& buffers, std::size_t v) {
  if (buffers.density(v).empty())
    throw Error(ErrorKind::invalid_argument,
                "measure mode: the buffers carry no density (BufferOptions::density is false)");
  const cv::Mat& rho = buffers.density(v);
  const cv::Mat& colour = buffers.colour_mass(v);
  constexpr double k = 4, gamma = 2.2;
  double max = 0;
  cv::minMaxLoc(rho, nullptr, &max);
  const int carrying = cv::countNonZero(rho > 0);
  cv::Mat out(rho.size(), CV_8UC3, cv::Scalar::all(0));
  if (max <= 0 || carrying == 0) return out;
  const double mean = 1.0 / carrying;  // ρ sums to 1
  const double norm = std::log1p(k * max / mean);
  for (int row = 0; row < rho.rows; ++row) {
    const float* src = rho.ptr<float>(row);
    const float* c = colour.ptr<float>(row);
    auto* dst = out.ptr<cv::Vec3b>(row);
    for (int col = 0; col < rho.cols; ++col) {
      if (!(src[col] > 0)) continue;
      const double t = std::pow(std::log1p(k * src[col] / mean) / norm, 1.0 / gamma);
      const Rgb hue = palette_ramp(c[col] / src[col]);
      const cv::Vec3b bgr(cv::saturate_cast<std::uint8_t>(t * hue.b * 255.0),
                          cv::saturate_cast<std::uint8_t>(t * hue.g * 255.0),
                          cv::saturate_cast<std::uint8_t>(t * hue.r * 255.0));
      // A pixel with mass is never black: it is on the set.
      dst[col] = bgr == cv::Vec3b::all(0) ? cv::Vec3b(1, 0, 0) : bgr;
    }
  }
  return out;
}

BufferOptions buffer_options(const SuperIfs& super, cv::Size size, const TextureOptions& options) {
  BufferOptions b;
  b.sampling = options.sampling;
  b.count = options.count;
  b.density = options.mode == TextureMode::measure;
  b.period = options.loop;
  if (options.mode == TextureMode::steal || options.mode == TextureMode::tops) {
    int pixels = std::max(size.width, size.height);
    if (!options.source.empty())
      pixels = std::max({pixels, options.source.cols, options.source.rows});
    b.history = options.mode == TextureMode::tops ? top_symbols : descent_depth(super, pixels);
  }
  return b;
}

void check_options(const TextureOptions& options) {
  if (options.count < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("count: the number of buffers must be ≥ 1 (got {})", options.count));
  if (options.buffer < 0 || options.buffer >= options.count)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("buffer: must be 0..{} for count = {} (got {})", options.count - 1,
                            options.count, options.buffer));
  if (options.steps < 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("steps: must be ≥ 0, 0 for the default (got {})", options.steps));
  if (options.loop < 0 || options.loop > kMaxLoop)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("loop: must be 0..{} textures, 0 for none (got {})", kMaxLoop, options.loop));
}

// What decides every later step of the buffers: the sets and, with densities, the measures and
// colour masses (the dilated masks, the history and the choices follow from them and the step).
struct BufferState {
  std::vector<cv::Mat> masks, densities, colours;

  BufferState(const Buffers& buffers, bool density) {
    for (std::size_t v = 0; v < buffers.count(); ++v) {
      masks.push_back(buffers.mask(v).clone());
      if (!density) continue;
      densities.push_back(buffers.density(v).clone());
      colours.push_back(buffers.colour_mass(v).clone());
    }
  }
};

// A float change of at most this much of the largest value is rounding: the measures of a closed
// loop keep changing in their last bits (float sums in a different order), about 1e-7 of it.
constexpr double measure_tolerance = 1e-6;

bool near_equal(const cv::Mat& a, const cv::Mat& b) {
  double largest = 0;
  cv::minMaxLoc(cv::abs(a), nullptr, &largest);
  return cv::norm(a, b, cv::NORM_INF) <= measure_tolerance * largest;
}

// Whether the buffers are back where `before` was: the sets bit for bit, the measures to rounding.
bool same_state(const BufferState& before, const Buffers& now) {
  for (std::size_t v = 0; v < before.masks.size(); ++v)
    if (cv::norm(before.masks[v], now.mask(v), cv::NORM_INF) != 0) return false;
  for (std::size_t v = 0; v < before.densities.size(); ++v)
    if (!near_equal(before.densities[v], now.density(v)) ||
        !near_equal(before.colours[v], now.colour_mass(v)))
      return false;
  return true;
}

}  // namespace

const char* to_string(TextureMode mode) noexcept {
  switch (mode) {
    case TextureMode::attractor:
      return "attractor";
    case TextureMode::tops:
      return "tops";
    case TextureMode::steal:
      return "steal";
    case TextureMode::measure:
      return "measure";
  }
  return "attractor";
}

TextureMode parse_texture_mode(const std::string& text, const std::string& what) {
  for (auto mode :
       {TextureMode::attractor, TextureMode::tops, TextureMode::steal, TextureMode::measure})
    if (text == to_string(mode)) return mode;
  throw Error(ErrorKind::parse,
              fmt::format("{}: must be attractor, tops, steal or measure (got '{}')", what, text));
}

int descent_depth(const SuperIfs& super, int pixels) {
  const double s = colouring_contraction(super);
  if (!(s > 0) || pixels <= 1) return 1;
  const double l = std::floor(std::log(static_cast<double>(pixels)) / -std::log(s)) + 1;
  return static_cast<int>(std::clamp(l, 1.0, 64.0));
}

StealMap steal_map(const Buffers& buffers, std::size_t v) {
  check_buffer(buffers, v);
  check_history(buffers, "steal map");
  const cv::Size size = buffers.size();
  const SuperIfs& super = buffers.super();
  std::vector<Ifs> colouring;
  for (std::size_t n = 0; n < super.size(); ++n) colouring.push_back(colouring_ifs(super, n));
  StealMap map;
  map.coverage = buffers.mask(v).clone();
  map.source_uv.create(size, CV_32FC2);
  const Descent descent(buffers);
  const auto band = [&](cv::Range rows) {
    std::vector<Symbol> word(descent.levels.size());
    Descent::Trail trail;
    for (int row = rows.start; row < rows.end; ++row) {
      auto* uv = map.source_uv.ptr<cv::Vec2f>(row);
      const std::uint8_t* covered = map.coverage.ptr<std::uint8_t>(row);
      for (int col = 0; col < size.width; ++col) {
        if (!covered[col]) {
          uv[col] = {0, 0};
          continue;
        }
        Point z;
        const std::size_t depth = descent.run(v, col, row, word, z, trail);
        // ρ: the buffers' rectangle onto the colouring's unit square (y up) — the steal
        // coordinates of the starting buffer — then T = g_{σ1} ∘ … ∘ g_{σL}(ρ(z)).
        Point t{z.x / size.width, 1.0 - z.y / size.height};
        for (std::size_t i = depth; i-- > 0;) t = colouring[word[i].n].maps[word[i].m](t);
        uv[col] = {static_cast<float>(t.x), static_cast<float>(1.0 - t.y)};
      }
    }
  };
  parallel_rows(size.height, band_rows, buffers.threads(), buffers.cancel(), "texture", band);
  return map;
}

cv::Mat render_buffer(const Buffers& buffers, std::size_t v, TextureMode mode,
                      const cv::Mat& source) {
  check_buffer(buffers, v);
  switch (mode) {
    case TextureMode::attractor:
      return buffers.mask(v).clone();
    case TextureMode::tops:
      return render_tops(buffers, v);
    case TextureMode::measure:
      return render_measure(buffers, v);
    case TextureMode::steal: {
      if (source.empty())
        throw Error(ErrorKind::invalid_argument,
                    "source: steal mode needs a source image to steal colours from");
      ApplyOptions apply_options;
      apply_options.threads = buffers.threads();
      return apply(steal_map(buffers, v), source, apply_options);
    }
  }
  return {};
}

cv::Mat render_texture(const SuperIfs& super, cv::Size size, const TextureOptions& options) {
  return TextureSequence(super, size, options).frame();
}

TextureSequence::TextureSequence(const SuperIfs& super, cv::Size size,
                                 const TextureOptions& options)
    : options_((check_options(options), options)),
      buffers_(super, size, buffer_options(super, size, options)) {
  burn_in_ = options.steps > 0 ? options.steps : default_steps(super, size);
  buffers_.run(burn_in_);
  if (options_.loop > 0) close_loop(burn_in_);
}

void TextureSequence::close_loop(int burn_in) {
  // The choices repeat every N steps (BufferOptions::period), and a step is a monotone map of the
  // sets (a union of lookups into dilated masks): from the full start the sets at the start of
  // each period only shrink, in a finite lattice, so they come back to themselves after some
  // period — and from then on the buffers repeat every N steps exactly (docs/design.md §12).
  const std::int64_t n = options_.loop;
  const std::int64_t limit = std::max<std::int64_t>(8 * static_cast<std::int64_t>(burn_in), 4 * n);
  loop_closed_ = false;
  for (std::int64_t done = 0; done < limit && !loop_closed_; done += n) {
    const BufferState before(buffers_, options_.mode == TextureMode::measure);
    buffers_.run(static_cast<int>(n));
    loop_closed_ = same_state(before, buffers_);
  }
  // The descent of tops and steal maps reads the last `history` steps: whole periods more until
  // they all lie on the loop.
  const auto history = static_cast<std::int64_t>(
      buffer_options(buffers_.super(), buffers_.size(), options_).history);
  if (loop_closed_ && history > n) buffers_.run(static_cast<int>(n * ((history + n - 1) / n - 1)));
  burn_in_ = buffers_.steps_done();
  // A copy: the buffers' images are replaced by each step, never written in place, so the copy's
  // stay as they are.
  loop_start_ = buffers_;
}

std::int64_t TextureSequence::in_loop(std::int64_t k) const {
  return options_.loop > 0 ? k % options_.loop : k;
}

cv::Mat TextureSequence::frame() const {
  return render_buffer(buffers_, static_cast<std::size_t>(options_.buffer), options_.mode,
                       options_.source);
}

StealMap TextureSequence::steal_map() const {
  return ifsfx::steal_map(buffers_, static_cast<std::size_t>(options_.buffer));
}

StealMap TextureSequence::next_map() {
  step();
  return steal_map();
}

namespace {

constexpr std::size_t kept_steps = 4;

void check_step(std::int64_t k) {
  if (k < 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("texture sequence: step must be 0 or more (got {})", k));
}

// Keeps step k's value, dropping the step farthest from k when more than kept_steps are kept.
template <class T>
void keep(std::map<std::int64_t, T>& kept, std::int64_t k, T value) {
  kept.emplace(k, std::move(value));
  while (kept.size() > kept_steps) {
    if (k - kept.begin()->first >= std::prev(kept.end())->first - k)
      kept.erase(kept.begin());
    else
      kept.erase(std::prev(kept.end()));
  }
}

}  // namespace

void TextureSequence::seek(std::int64_t k) {
  if (k < buffers_.steps_done() - burn_in_ && loop_start_) {
    buffers_ = *loop_start_;
  } else if (k < buffers_.steps_done() - burn_in_) {
    // Each step's choices come from stream_seed(seed, step): the same steps again give the same
    // buffers.
    const SuperIfs super = buffers_.super();
    const cv::Size size = buffers_.size();
    buffers_ = Buffers(super, size, buffer_options(super, size, options_));
    buffers_.run(burn_in_);
  }
  while (buffers_.steps_done() - burn_in_ < k) buffers_.step();
}

StealMap TextureSequence::map_at(std::int64_t k) {
  check_step(k);
  k = in_loop(k);
  std::lock_guard lock(mutex_);
  if (const auto it = kept_maps_.find(k); it != kept_maps_.end()) return it->second;
  if (k < buffers_.steps_done() - burn_in_) seek(k);
  // Every map on the way is kept too: a schedule that asks for k + 2 before k + 1 finds it.
  for (;;) {
    const std::int64_t at = buffers_.steps_done() - burn_in_;
    if (!kept_maps_.contains(at)) keep(kept_maps_, at, steal_map());
    if (at == k) return kept_maps_.at(k);
    buffers_.step();
  }
}

cv::Mat TextureSequence::frame_at(std::int64_t k) {
  check_step(k);
  k = in_loop(k);
  std::lock_guard lock(mutex_);
  if (const auto it = kept_frames_.find(k); it != kept_frames_.end()) return it->second;
  seek(k);
  cv::Mat image = frame();
  keep(kept_frames_, k, image);
  return image;
}

cv::Mat TextureSequence::frame_at(StepPosition position) {
  cv::Mat image = frame_at(position.step);
  if (position.phase <= 0) return image;
  return crossfade(image, frame_at(position.step + 1), position.phase);
}

cv::Mat crossfade(const cv::Mat& a, const cv::Mat& b, double t) {
  if (a.size() != b.size() || a.type() != b.type())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("crossfade: images must share size and type (got {}x{} and {}x{})",
                            a.cols, a.rows, b.cols, b.rows));
  if (!(t >= 0 && t <= 1))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("crossfade: t must be in [0, 1] (got {})", t));
  cv::Mat out;
  cv::addWeighted(a, 1.0 - t, b, t, 0.0, out);
  return out;
}

}  // namespace ifsfx
