// SPDX-License-Identifier: Apache-2.0
// The V buffers of a V-variable superfractal (paper §5, eq. 13–14; docs/design.md §5).
//
// One step, for each buffer v: pick n_v ~ P; for each map m pick a source buffer v_m uniformly in
// 1..V; then K'_v = Top-union over m of f^{n_v}_m(K_{v_m}), painted in increasing m so that the
// higher m is on top. All V buffers are replaced at once. After enough steps every buffer is a
// V-variable fractal, and every further step yields a new member of the same family.
//
// Rasterised by inverse mapping: pixel x of K'_v is set when, for some m, f_m⁻¹(x) falls in
// K_{v_m}. The lookup is conservative — into K_{v_m} dilated by about the preimage of a pixel —
// since a nearest-pixel lookup erodes thin shapes to dust within a few steps (docs/design.md §3).
// x stays in floating point; the buffers share one plane rectangle (buffer_view()), and a shape
// cut by its edge is still exact once burnt in, because the union attractor lies inside it.
//
// The buffers keep the last `history` steps (their choices and dilated masks) so that the steal
// coordinates and tops of a buffer can be found exactly by descent (texture.h), and optionally a
// density per buffer, the pushed-forward measure μ'_v = Σ_m p^{n_v}_m f_m#(μ_{v_m}).
//
// Every random choice of step k comes from stream_seed(seed, k): same seed ⇒ same buffers for
// any thread count.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/cancel.h"
#include "ifs/sampling.h"
#include "ifs/view.h"
#include "superifs/superifs.h"

namespace ifsfx {

// A raster mask packed 8 pixels to a byte: the history of a few dozen steps of V buffers at
// 8192×8192 fits in a few hundred MiB.
class BitMask {
 public:
  BitMask() = default;
  // Packs a CV_8UC1 mask (nonzero = set).
  explicit BitMask(const cv::Mat& mask);

  // Whether the pixel holding the continuous pixel coordinates (x, y) is set; false outside. A
  // point within `edge` of the raster's border counts as on it: preimages of points on a piece's
  // edge land on the border up to rounding, and pieces are closed sets (tops keep the higher m).
  bool test(double x, double y) const noexcept {
    constexpr double edge = 1e-7;
    if (!(x >= -edge && y >= -edge && x < width_ + edge && y < height_ + edge)) return false;
    // Signed conversions: double → unsigned 64-bit has no single instruction on x86-64.
    const int c = std::min(static_cast<int>(std::max(x, 0.0)), width_ - 1);
    const int r = std::min(static_cast<int>(std::max(y, 0.0)), height_ - 1);
    return test(c, r);
  }
  bool test(int col, int row) const noexcept {
    return (bits_[static_cast<std::size_t>(row) * stride_ + (static_cast<std::size_t>(col) >> 3)] >>
            (col & 7)) &
           1u;
  }
  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  // Rows [row0, row1) packed from a CV_8UC1 mask of the same size (for row-parallel packing).
  void pack_rows(const cv::Mat& mask, int row0, int row1);
  void resize(cv::Size size);

 private:
  int width_ = 0, height_ = 0;
  std::size_t stride_ = 0;  // bytes per row
  std::vector<std::uint8_t> bits_;
};

// The random choices of one step (eq. 14), indices from 0.
struct StepChoices {
  std::vector<std::uint32_t> ifs;     // n_v for each buffer v
  std::vector<std::uint32_t> source;  // v_m for buffer v and map m at [v · M + m]
};

// What the descent of step k needs: the choices that made step k and the dilated masks of
// step k − 1 they looked up.
struct HistoryLevel {
  StepChoices choices;
  std::vector<BitMask> previous;  // conservative (dilated) masks of the V buffers before the step
};

struct BufferOptions {
  int count = 3;  // V, the number of buffers
  // The plane rectangle (default: the superIFS's view, else buffer_view()'s framing with the
  // margin); the choices of step k come from stream_seed(seed, k); threads (0 = all cores); the
  // stop flag, polled per band of rows of a step. Quality is not used: buffers are rasters. With
  // sampling.seamless the buffers live on the torus of their rectangle (docs/design.md §11): each
  // f^n_m is followed by the wrap back into it, so pixel x of K'_v is set when f_m⁻¹(x + λ) falls
  // in K_{v_m} for some translate of x by the lattice of the tile, and the dilation, the smoothing
  // and every lookup wrap around its edges.
  Sampling sampling;
  int history = 0;       // steps kept for the exact descent (steal coordinates, tops); 0 = none
  bool density = false;  // also carry the measures (measure mode)
  // With period P > 0 the choices of step k come from stream_seed(seed, k mod P) instead: a
  // periodic choice stream, whose buffers close into a loop (docs/design.md §12). 0 = none.
  std::int64_t period = 0;
};

class Buffers {
 public:
  // V buffers on `size` pixels, each the whole plane rectangle (and, with density, a uniform
  // measure on it). Throws Error{invalid_argument} for a bad size, count or history, and the
  // errors of validate(SuperIfs).
  //   Buffers K(super, {1024, 1024}, {.count = 3});
  //   K.run(default_steps(super, {1024, 1024}));
  Buffers(const SuperIfs& super, cv::Size size, const BufferOptions& options = {});

  // Replaces the starting buffers (CV_8UC1 of the raster's size, nonzero = set; densities become
  // uniform on each mask). Only before the first step; throws Error{invalid_argument} after it.
  void set_masks(const std::vector<cv::Mat>& masks);

  // One step of eq. 14 for all V buffers at once.
  void step();
  void run(int steps);

  std::size_t count() const { return masks_.size(); }  // V
  int steps_done() const { return steps_; }
  cv::Size size() const { return viewport_.size; }
  const Viewport& viewport() const { return viewport_; }
  const SuperIfs& super() const { return super_; }
  int threads() const { return options_.sampling.threads; }
  const CancelToken& cancel() const { return options_.sampling.cancel; }

  // The set K_v: CV_8UC1, 255 on the set, 0 elsewhere.
  const cv::Mat& mask(std::size_t v) const { return masks_.at(v); }
  // The measure μ_v: CV_32FC1 mass per pixel summing to 1 (empty without options.density).
  const cv::Mat& density(std::size_t v) const { return densities_.at(v); }
  // The palette coordinate carried with that mass, ∫ c dμ_v per pixel (CV_32FC1): each step
  // takes c to (c + c_m) / 2 on the mass map m moves, c_m = m / (M − 1) (docs/design.md §4, the
  // chaos game's c_k = (c_{k−1} + c_σk) / 2 in expectation). colour_mass / density is the pixel's
  // mean coordinate in [0, 1], so the measure can be coloured by map.
  const cv::Mat& colour_mass(std::size_t v) const { return colour_masses_.at(v); }

  // The last min(history, steps_done()) levels, oldest first; back() made the current buffers.
  const std::deque<HistoryLevel>& history() const { return history_; }
  // The choices of the last step (empty before the first).
  const StepChoices& last_choices() const { return last_choices_; }

  // The inverse of f^n_m in continuous pixel coordinates of the raster (n, m from 0).
  const AffineMap& pixel_inverse(std::size_t n, std::size_t m) const {
    return pixel_inverse_[n * super_.maps() + m];
  }
  // A box (continuous pixel coordinates) holding f^n_m of the whole raster with the lookup's reach
  // to spare: no point outside it has its preimage under f^n_m in a buffer.
  const Box& piece_bounds(std::size_t n, std::size_t m) const {
    return piece_bounds_[n * super_.maps() + m];
  }
  // Half-width in pixels of the dilation that makes the lookup conservative.
  int dilation() const { return dilation_; }
  // Whether the buffers live on the torus of their rectangle (BufferOptions::sampling.seamless).
  bool seamless() const { return viewport_.wrap; }

 private:
  struct Next;  // the buffers a step makes (buffers.cpp)
  StepChoices draw_choices() const;
  void dilate_current();
  void smooth_densities(Next& next) const;
  void paint_next(const StepChoices& choices, Next& next) const;
  void paint_mask_row(const StepChoices& choices, std::size_t v, int row, Next& next) const;
  void paint_mass_row(const StepChoices& choices, const std::vector<double>& map_coordinate,
                      std::size_t v, int row, Next& next) const;
  void take_next(const StepChoices& choices, Next& next);

  SuperIfs super_;
  BufferOptions options_;
  Viewport viewport_;
  std::vector<AffineMap> pixel_inverse_;                // [n · M + m]
  std::vector<Box> piece_bounds_;                       // [n · M + m]
  std::vector<std::vector<double>> map_probabilities_;  // p^n_m
  std::vector<double> ifs_probabilities_;               // P_n
  int dilation_ = 1;
  int steps_ = 0;
  std::vector<cv::Mat> masks_;          // K_v
  std::vector<BitMask> dilated_;        // K_v dilated, what the next step looks up
  std::vector<cv::Mat> densities_;      // μ_v
  std::vector<cv::Mat> colour_masses_;  // ∫ c dμ_v
  std::deque<HistoryLevel> history_;
  StepChoices last_choices_;
};

}  // namespace ifsfx
