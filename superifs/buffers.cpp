// SPDX-License-Identifier: Apache-2.0
#include "superifs/buffers.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx {

namespace {

// Rows per chunk of work. Fixed, so that the split never depends on the thread count.
constexpr int band_rows = 16;

// The plane → continuous pixel coordinates map of a viewport (y up in the plane, rows down).
AffineMap plane_to_pixel(const Viewport& vp) {
  const double sx = vp.size.width / vp.view.width();
  const double sy = vp.size.height / vp.view.height();
  return {sx, 0, 0, -sy, -vp.view.x0 * sx, vp.view.y1 * sy};
}

// Chebyshev half-width, in pixels, of the preimage of a pixel under `inverse` (pixel space).
double footprint(const AffineMap& inverse) {
  return 0.5 * std::max(std::abs(inverse.a) + std::abs(inverse.b),
                        std::abs(inverse.c) + std::abs(inverse.d));
}

// Row k of a raster of `h` rows seen from a window around `row`: on the torus (`wrap`) the rows
// wrap around; else -1 outside.
int window_row(int k, int h, bool wrap) {
  if (wrap) return ((k % h) + h) % h;
  return k >= 0 && k < h ? k : -1;
}

// Rows [row0, row1) of `out` = `mask` dilated by a (2r+1)² square, separably: an OR over rows,
// then over columns. Reads rows of `mask` up to r outside the band; on the torus (`wrap`) the
// square wraps around the raster's edges.
void dilate_rows(const cv::Mat& mask, int r, int row0, int row1, bool wrap, BitMask& out) {
  const int w = mask.cols, h = mask.rows;
  std::vector<std::uint8_t> column(static_cast<std::size_t>(w)), both(static_cast<std::size_t>(w));
  cv::Mat packed(1, w, CV_8UC1);
  for (int row = row0; row < row1; ++row) {
    std::fill(column.begin(), column.end(), 0);
    // On the torus a square wider than the raster covers it once: min(2r+1, h) rows.
    const int k0 = wrap ? row - std::min(r, (h - 1) / 2) : std::max(0, row - r);
    const int k1 = wrap ? k0 + std::min(2 * r, h - 1) : std::min(h - 1, row + r);
    for (int k = k0; k <= k1; ++k) {
      const std::uint8_t* src = mask.ptr<std::uint8_t>(window_row(k, h, wrap));
      for (int c = 0; c < w; ++c) column[static_cast<std::size_t>(c)] |= src[c];
    }
    std::copy(column.begin(), column.end(), both.begin());
    for (int k = 1; k <= r; ++k) {
      for (int c = 0; c + k < w; ++c)
        both[static_cast<std::size_t>(c)] |= column[static_cast<std::size_t>(c + k)];
      for (int c = k; c < w; ++c)
        both[static_cast<std::size_t>(c)] |= column[static_cast<std::size_t>(c - k)];
      if (!wrap) continue;
      // The columns whose window runs off an edge read the opposite edge's.
      for (int c = std::max(0, w - k); c < w; ++c)
        both[static_cast<std::size_t>(c)] |= column[static_cast<std::size_t>((c + k) % w)];
      for (int c = 0; c < std::min(k, w); ++c)
        both[static_cast<std::size_t>(c)] |=
            column[static_cast<std::size_t>(((c - k) % w + w) % w)];
    }
    std::copy(both.begin(), both.end(), packed.ptr<std::uint8_t>(0));
    out.pack_rows(packed, row, row + 1);
  }
}

// Rows [row0, row1) of `out` = the (2r+1)² box average of `density` on the torus: the window
// wraps around the raster's edges (a window wider than the raster covers it once).
void box_rows_wrapped(const cv::Mat& density, int r, int row0, int row1, cv::Mat& out) {
  const int w = density.cols, h = density.rows;
  const int ry = std::min(r, (h - 1) / 2), rx = std::min(r, (w - 1) / 2);
  const int rows = 2 * ry + 1, cols = 2 * rx + 1;
  std::vector<double> column(static_cast<std::size_t>(w));
  for (int row = row0; row < row1; ++row) {
    std::fill(column.begin(), column.end(), 0.0);
    for (int k = row - ry; k <= row + ry; ++k) {
      const float* src = density.ptr<float>(window_row(k, h, true));
      for (int c = 0; c < w; ++c) column[static_cast<std::size_t>(c)] += src[c];
    }
    float* dst = out.ptr<float>(row);
    for (int c = 0; c < w; ++c) {
      double sum = 0;
      for (int k = c - rx; k <= c + rx; ++k)
        sum += column[static_cast<std::size_t>(window_row(k, w, true))];
      dst[c] = static_cast<float>(sum / (rows * cols));
    }
  }
}

// Rows [row0, row1) of `out` = the (2r+1)² box average of `density` (edges: the window is cut,
// the average is over the pixels inside). Smooths μ over about a pixel's preimage before the
// point lookup of the push-forward, so that fine structure is averaged, not aliased.
void box_rows(const cv::Mat& density, int r, int row0, int row1, cv::Mat& out) {
  const int w = density.cols, h = density.rows;
  std::vector<double> column(static_cast<std::size_t>(w));
  for (int row = row0; row < row1; ++row) {
    std::fill(column.begin(), column.end(), 0.0);
    const int k0 = std::max(0, row - r), k1 = std::min(h - 1, row + r);
    for (int k = k0; k <= k1; ++k) {
      const float* src = density.ptr<float>(k);
      for (int c = 0; c < w; ++c) column[static_cast<std::size_t>(c)] += src[c];
    }
    float* dst = out.ptr<float>(row);
    double sum = 0;
    int lo = 0, hi = -1;  // the running window [lo, hi] of columns
    int filled = 0;       // columns of the window with mass
    for (int c = 0; c < w; ++c) {
      while (hi < std::min(w - 1, c + r)) {
        const double add = column[static_cast<std::size_t>(++hi)];
        sum += add;
        filled += add != 0;
      }
      while (lo < c - r) {
        const double drop = column[static_cast<std::size_t>(lo++)];
        sum -= drop;
        filled -= drop != 0;
      }
      // A running difference leaves a residue (~1e-20) once the mass has left the window; an
      // empty window is exactly 0, so the measure's support stays the mask (same reach).
      if (filled == 0) sum = 0;
      dst[c] = static_cast<float>(sum / ((hi - lo + 1) * (k1 - k0 + 1)));
    }
  }
}

// The pixel centres px of a row for which slope·px + offset may lie in [0, limit): narrows
// [lo, hi] (continuous column coordinates), with a pixel to spare on each side.
void narrow(double slope, double offset, double limit, double& lo, double& hi) {
  if (slope == 0) {
    if (!(offset >= -1 && offset <= limit + 1)) hi = lo - 1;
    return;
  }
  double p0 = (-1 - offset) / slope, p1 = (limit + 1 - offset) / slope;
  if (p0 > p1) std::swap(p0, p1);
  lo = std::max(lo, p0);
  hi = std::min(hi, p1);
}

// Translates i·W, j·H of the lattice of the tile, i in [i0, i1], j in [j0, j1] (paint_next).
struct LatticeRange {
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
};

// The translates by the lattice of the tile that can put row py (and column px, when given) in
// a piece's box `b` (pixel coordinates): i·W and j·H for i in [i0, i1], j in [j0, j1]; only
// (0, 0) off the torus.
LatticeRange lattice_translates(const Viewport& vp, const Box& b, double py, double px = NAN) {
  if (!vp.wrap) return LatticeRange{};
  const double w = vp.size.width, h = vp.size.height;
  LatticeRange r;
  r.j0 = static_cast<int>(std::ceil((b.y0 - py) / h));
  r.j1 = static_cast<int>(std::floor((b.y1 - py) / h));
  if (std::isnan(px)) {
    r.i0 = static_cast<int>(std::floor(b.x0 / w));
    r.i1 = static_cast<int>(std::floor(b.x1 / w));
  } else {
    r.i0 = static_cast<int>(std::ceil((b.x0 - px) / w));
    r.i1 = static_cast<int>(std::floor((b.x1 - px) / w));
  }
  return r;
}

}  // namespace

BitMask::BitMask(const cv::Mat& mask) {
  resize(mask.size());
  pack_rows(mask, 0, mask.rows);
}

void BitMask::resize(cv::Size size) {
  width_ = size.width;
  height_ = size.height;
  stride_ = (static_cast<std::size_t>(width_) + 7) / 8;
  bits_.assign(stride_ * static_cast<std::size_t>(height_), 0);
}

void BitMask::pack_rows(const cv::Mat& mask, int row0, int row1) {
  const auto w = static_cast<std::size_t>(width_);
  for (int row = row0; row < row1; ++row) {
    const std::uint8_t* src = mask.ptr<std::uint8_t>(mask.rows == 1 ? 0 : row);
    std::uint8_t* dst = bits_.data() + static_cast<std::size_t>(row) * stride_;
    std::size_t byte = 0;
    for (; (byte + 1) * 8 <= w; ++byte) {
      // Eight mask bytes to eight bits at once: each byte becomes 0 or 1, and the multiply moves
      // byte k's bit to bit 56 + k without carries (all partial products are distinct powers).
      std::uint64_t eight = 0;
      for (std::size_t k = 0; k < 8; ++k)
        eight |= static_cast<std::uint64_t>(src[byte * 8 + k] != 0) << (8 * k);
      dst[byte] = static_cast<std::uint8_t>((eight * 0x0102040810204080ULL) >> 56);
    }
    for (; byte < stride_; ++byte) {
      std::uint8_t b = 0;
      for (std::size_t k = 0; byte * 8 + k < w; ++k)
        b |= static_cast<std::uint8_t>((src[byte * 8 + k] != 0) << k);
      dst[byte] = b;
    }
  }
}

Buffers::Buffers(const SuperIfs& super, cv::Size size, const BufferOptions& options)
    : super_(super), options_(options) {
  validate(super_, super_.name.empty() ? std::string("superIFS") : super_.name);
  check_size(size);
  if (options.count < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("count: the number of buffers must be ≥ 1 (got {})", options.count));
  if (options.history < 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("history: must be ≥ 0 steps (got {})", options.history));
  resolve_threads(options.sampling.threads);  // rejects a negative count up front
  if (options.sampling.view) check_view(*options.sampling.view);
  viewport_ = {buffer_view(super_, size, options.sampling), size, options.sampling.seamless};
  const AffineMap to_pixel = plane_to_pixel(viewport_);
  const AffineMap to_plane = *to_pixel.inverse();
  const std::size_t n_count = super_.size(), m_count = super_.maps();
  double widest = 0;
  for (std::size_t n = 0; n < n_count; ++n) {
    for (std::size_t m = 0; m < m_count; ++m) {
      // A = P ∘ (f^n_m)⁻¹ ∘ P⁻¹: the inverse map acting on pixel coordinates.
      const AffineMap a = to_pixel.compose(super_.ifs[n].maps[m].inverse()->compose(to_plane));
      pixel_inverse_.push_back(a);
      widest = std::max(widest, footprint(a));
    }
    map_probabilities_.push_back(effective_probabilities(super_.ifs[n]));
  }
  ifs_probabilities_ = effective_probabilities(super_);
  // The lookup reaches the pixel under f⁻¹(x) and `dilation_` more on each side: enough to meet
  // every pixel the preimage of x's pixel touches, to within half a pixel (docs/design.md §3).
  dilation_ = std::clamp(static_cast<int>(std::ceil(widest - 0.5)), 1, 32);
  for (const AffineMap& a : pixel_inverse_) {
    const AffineMap f = *a.inverse(0);
    const double w = size.width, h = size.height;
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const Point corner : {Point{0, 0}, Point{w, 0}, Point{0, h}, Point{w, h}}) {
      const Point p = f(corner);
      b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
    }
    const double reach = dilation_ + 2;
    piece_bounds_.push_back({b.x0 - reach, b.y0 - reach, b.x1 + reach, b.y1 + reach});
  }
  std::vector<cv::Mat> full(static_cast<std::size_t>(options.count),
                            cv::Mat(size, CV_8UC1, cv::Scalar(255)));
  set_masks(full);
}

void Buffers::set_masks(const std::vector<cv::Mat>& masks) {
  if (steps_ != 0)
    throw Error(ErrorKind::invalid_argument,
                "set_masks: starting buffers can only be set before the first step");
  if (masks.size() != static_cast<std::size_t>(options_.count))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("set_masks: one mask per buffer is needed (got {} for V = {})",
                            masks.size(), options_.count));
  masks_.clear();
  densities_.clear();
  colour_masses_.clear();
  for (const auto& m : masks) {
    if (m.size() != viewport_.size || m.type() != CV_8UC1)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("set_masks: masks must be CV_8UC1 of {}x{} (got {}x{})",
                              viewport_.size.width, viewport_.size.height, m.cols, m.rows));
    cv::Mat binary;
    cv::compare(m, 0, binary, cv::CMP_NE);
    masks_.push_back(binary);
    if (options_.density) {
      cv::Mat d;
      binary.convertTo(d, CV_32F, 1.0 / 255.0);
      const double total = cv::sum(d)[0];
      if (total > 0) d /= total;
      densities_.push_back(d);
      colour_masses_.push_back(d * 0.5);  // mid-palette to start; halved away at every step
    }
  }
  dilate_current();
}

void Buffers::dilate_current() {
  const std::size_t v_count = masks_.size();
  dilated_.assign(v_count, BitMask());
  for (auto& d : dilated_) d.resize(viewport_.size);
  parallel_rows(v_count, viewport_.size.height, band_rows, options_.sampling.threads,
                options_.sampling.cancel, "superIFS step", [&](std::size_t v, cv::Range rows) {
                  dilate_rows(masks_[v], dilation_, rows.start, rows.end, viewport_.wrap,
                              dilated_[v]);
                });
}

StepChoices Buffers::draw_choices() const {
  const std::size_t v_count = masks_.size(), m_count = super_.maps();
  // One stream per step: the choices never depend on threads or on the raster. A periodic stream
  // repeats the choices of its first period.
  const std::int64_t k = options_.period > 0 ? steps_ % options_.period : steps_;
  Rng rng(stream_seed(options_.sampling.seed, static_cast<std::uint64_t>(k)));
  const MapPicker pick_ifs(ifs_probabilities_);
  StepChoices c;
  c.ifs.resize(v_count);
  c.source.resize(v_count * m_count);
  for (std::size_t v = 0; v < v_count; ++v) {
    c.ifs[v] = pick_ifs(rng.next());
    for (std::size_t m = 0; m < m_count; ++m)
      c.source[v * m_count + m] = rng.below(static_cast<std::uint32_t>(v_count));
  }
  return c;
}

// What a step makes: K'_v and, with densities, μ'_v and the colour masses, from the smoothed μ_v
// and colour masses it reads.
struct Buffers::Next {
  std::vector<cv::Mat> masks;
  std::vector<cv::Mat> smooth, smooth_colour, density, colour;
};

void Buffers::step() {
  const StepChoices choices = draw_choices();
  const std::size_t v_count = masks_.size();
  const cv::Size size = viewport_.size;
  Next next;
  next.masks.resize(v_count);
  for (auto& k : next.masks) k.create(size, CV_8UC1);
  if (options_.density) {
    for (auto* mats : {&next.smooth, &next.smooth_colour, &next.density, &next.colour}) {
      mats->resize(v_count);
      for (cv::Mat& m : *mats) m.create(size, CV_32FC1);
    }
    smooth_densities(next);
  }
  paint_next(choices, next);
  take_next(choices, next);
}

// The densities and colour masses averaged over the dilation's window, by bands of rows.
void Buffers::smooth_densities(Next& next) const {
  parallel_rows(masks_.size(), viewport_.size.height, band_rows, options_.sampling.threads,
                options_.sampling.cancel, "superIFS step", [&](std::size_t v, cv::Range rows) {
                  const auto box = viewport_.wrap ? box_rows_wrapped : box_rows;
                  box(densities_[v], dilation_, rows.start, rows.end, next.smooth[v]);
                  box(colour_masses_[v], dilation_, rows.start, rows.end, next.smooth_colour[v]);
                });
}

// K'_v (and μ'_v with the colour masses) from the buffers the choices draw on, by bands of rows.
void Buffers::paint_next(const StepChoices& choices, Next& buffers) const {
  const std::size_t m_count = super_.maps();
  // c_m of map m: its place on the palette.
  std::vector<double> map_coordinate(m_count, 0.0);
  for (std::size_t m = 0; m < m_count && m_count > 1; ++m)
    map_coordinate[m] = static_cast<double>(m) / static_cast<double>(m_count - 1);
  parallel_rows(masks_.size(), viewport_.size.height, band_rows, options_.sampling.threads,
                options_.sampling.cancel, "superIFS step", [&](std::size_t v, cv::Range rows) {
                  for (int row = rows.start; row < rows.end; ++row) {
                    paint_mask_row(choices, v, row, buffers);
                    if (options_.density) paint_mass_row(choices, map_coordinate, v, row, buffers);
                  }
                });
}

// Row `row` of K'_v = ∪_m f_m(K_{v_m}) (eq. 14). For the set the painting order does not matter
// (the descent applies the tops rule); each map is tried only on the columns whose preimage can
// fall inside the raster.
void Buffers::paint_mask_row(const StepChoices& choices, std::size_t v, int row,
                             Next& buffers) const {
  const std::size_t m_count = super_.maps();
  const cv::Size size = viewport_.size;
  const std::uint32_t n = choices.ifs[v];
  const std::uint32_t* source = &choices.source[v * m_count];
  std::uint8_t* out = buffers.masks[v].ptr<std::uint8_t>(row);
  std::fill(out, out + size.width, std::uint8_t{0});
  const double py = row + 0.5;
  for (std::size_t m = 0; m < m_count; ++m) {
    const AffineMap& a = pixel_inverse_[n * m_count + m];
    const BitMask& from = dilated_[source[m]];
    // On the torus, every translate x + λ of the row by the lattice, λ = (i·W, j·H), that can lie
    // in the piece f_m(tile) (docs/design.md §11); else λ = 0 alone.
    const LatticeRange range = lattice_translates(viewport_, piece_bounds_[n * m_count + m], py);
    for (int j = range.j0; j <= range.j1; ++j)
      for (int i = range.i0; i <= range.i1; ++i) {
        const double ty = py + j * static_cast<double>(size.height);
        const double tx = i * static_cast<double>(size.width);
        // The preimage of (px + tx, ty): a.a·px + (a.a·tx + a.b·ty + a.e), likewise y.
        const double ox = a.a * tx + a.b * ty + a.e, oy = a.c * tx + a.d * ty + a.f;
        double lo = 0.5, hi = size.width - 0.5;
        narrow(a.a, ox, size.width, lo, hi);
        narrow(a.c, oy, size.height, lo, hi);
        if (hi < lo) continue;
        const int c0 = std::max(0, static_cast<int>(std::floor(lo - 0.5)));
        const int c1 = std::min(size.width - 1, static_cast<int>(std::ceil(hi - 0.5)));
        for (int col = c0; col <= c1; ++col) {
          // (px + tx, ty): the pixel centre itself off the torus (tx = 0, ty = py).
          const double qx = col + 0.5 + tx;
          if (!out[col] && from.test(a.a * qx + a.b * ty + a.e, a.c * qx + a.d * ty + a.f))
            out[col] = 255;
        }
      }
  }
}

// Row `row` of μ'_v = Σ_m p^{n}_m f_m#(μ_{v_m}): the mass of pixel x is the mass of its
// preimage, |det f_m⁻¹| pixels of the smoothed density around f_m⁻¹(x). The palette coordinate
// rides along: (c + c_m) / 2 on what map m carries.
void Buffers::paint_mass_row(const StepChoices& choices, const std::vector<double>& map_coordinate,
                             std::size_t v, int row, Next& buffers) const {
  const std::size_t m_count = super_.maps();
  const cv::Size size = viewport_.size;
  const std::uint32_t n = choices.ifs[v];
  const std::uint32_t* source = &choices.source[v * m_count];
  const double py = row + 0.5;
  float* mass = buffers.density[v].ptr<float>(row);
  float* colour = buffers.colour[v].ptr<float>(row);
  for (int col = 0; col < size.width; ++col) {
    const double px = col + 0.5;
    double sum = 0, colour_sum = 0;
    for (std::size_t m = 0; m < m_count; ++m) {
      const AffineMap& a = pixel_inverse_[n * m_count + m];
      const double weight = map_probabilities_[n][m] * std::abs(a.det());
      // On the torus the mass of every translate's preimage in the tile.
      const LatticeRange range =
          lattice_translates(viewport_, piece_bounds_[n * m_count + m], py, px);
      for (int j = range.j0; j <= range.j1; ++j)
        for (int i = range.i0; i <= range.i1; ++i) {
          const double tx = px + i * static_cast<double>(size.width);
          const double ty = py + j * static_cast<double>(size.height);
          const double x = a.a * tx + a.b * ty + a.e, y = a.c * tx + a.d * ty + a.f;
          if (!(x >= 0 && y >= 0 && x < size.width && y < size.height)) continue;
          const int ix = static_cast<int>(x), iy = static_cast<int>(y);
          const float rho = buffers.smooth[source[m]].at<float>(iy, ix);
          const float rho_c = buffers.smooth_colour[source[m]].at<float>(iy, ix);
          sum += weight * rho;
          colour_sum += weight * 0.5 * (rho_c + map_coordinate[m] * rho);
        }
    }
    mass[col] = static_cast<float>(sum);
    colour[col] = static_cast<float>(colour_sum);
  }
}

// The new buffers become the current ones; the step is counted (and kept in the history).
void Buffers::take_next(const StepChoices& choices, Next& buffers) {
  const std::size_t v_count = masks_.size();
  std::vector<cv::Mat>& next = buffers.masks;
  std::vector<cv::Mat>& next_density = buffers.density;
  std::vector<cv::Mat>& next_colour = buffers.colour;
  if (options_.density) {
    for (std::size_t v = 0; v < v_count; ++v) {
      // Mass that left the rectangle is put back by normalising: μ_v stays a probability.
      const double total = cv::sum(next_density[v])[0];
      if (total > 0) {
        next_density[v] /= total;
        next_colour[v] /= total;
      }
    }
    densities_ = std::move(next_density);
    colour_masses_ = std::move(next_colour);
  }
  masks_ = std::move(next);
  if (options_.history > 0) {
    history_.push_back({choices, std::move(dilated_)});
    while (history_.size() > static_cast<std::size_t>(options_.history)) history_.pop_front();
  }
  last_choices_ = choices;
  ++steps_;
  dilate_current();
}

void Buffers::run(int steps) {
  if (steps < 0)
    throw Error(ErrorKind::invalid_argument, fmt::format("steps: must be ≥ 0 (got {})", steps));
  for (int k = 0; k < steps; ++k) step();
}

}  // namespace ifsfx
