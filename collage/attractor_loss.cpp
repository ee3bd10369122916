// SPDX-License-Identifier: Apache-2.0
#include "collage/attractor_loss.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/detail/play_kernel.h"
#include "collage/distance.h"
#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/ifs.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

namespace {

// Chaos-game steps before the first point counts: from the square's centre, s^24 of the
// square's size away from A at worst.
constexpr std::size_t kBurnIn = 24;
constexpr std::size_t kLanes = detail::kPlayLanes;

}  // namespace

AttractorLoss::AttractorLoss(const cv::Mat& target, const AttractorLossOptions& options)
    : options_(options) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "attractor loss: the target must be a non-empty square CV_8UC1 working raster");
  if (options.size < 8 || options.size > target.cols)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("attractor loss: the level's size must be in 8..{} (got {})",
                            target.cols, options.size));
  if (!(options.keep >= 0 && options.keep < 1))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("attractor loss: keep must be in [0, 1) (got {})", options.keep));
  if (!(options.points > 0))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("attractor loss: points per pixel must be > 0 (got {})", options.points));
  size_ = options.size;
  pad_ = size_ / 4;
  side_ = size_ + 2 * pad_;
  target_ = resampled_mask(target, size_, options.keep);
  if (cv::countNonZero(target_) == 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("attractor loss: the target vanishes on a {}² raster", size_));
  cv::Mat canvas(side_, side_, CV_8UC1, cv::Scalar(0));
  target_.copyTo(canvas(cv::Rect(pad_, pad_, size_, size_)));
  const cv::Mat distance = distance_to(canvas);
  cells_.assign(4 * static_cast<std::size_t>(side_ * side_), 0.0f);
  for (int r = 0; r + 1 < side_; ++r)
    for (int c = 0; c + 1 < side_; ++c) {
      float* cell = cells_.data() + 4 * static_cast<std::size_t>(r * side_ + c);
      cell[0] = distance.at<float>(r, c);
      cell[1] = distance.at<float>(r, c + 1);
      cell[2] = distance.at<float>(r + 1, c);
      cell[3] = distance.at<float>(r + 1, c + 1);
    }
  for (int i = 0; i < side_ * side_; ++i)
    if (canvas.data[i]) {
      inside_.push_back(i);
      inside_at_.emplace_back(i % side_, i / side_);
    }
  bounds_ = cv::boundingRect(canvas);
  // Each lane's run of the draws is the next `steps` numbers of one stream, stored step-major
  // (draws_[8 t + lane]) for the kernels' one load a step.
  Rng rng(stream_seed(options.seed, 0x61747472ULL));
  const std::size_t steps =
      static_cast<std::size_t>(options.points * size_ * size_) / kLanes + kBurnIn;
  draws_.resize(kLanes * steps);
  for (std::size_t lane = 0; lane < kLanes; ++lane)
    for (std::size_t t = 0; t < steps; ++t)
      draws_[t * kLanes + lane] = static_cast<float>(rng.uniform());
  level_ = options.level.value_or(cpu_level());
}

double AttractorLoss::play(std::span<const AffineMap> maps, std::vector<std::uint8_t>* hits) const {
  // Probabilities ∝ |det| (the renderer's default, ifs.h): the points spread evenly over A.
  const std::vector<double> p = default_probabilities({maps.begin(), maps.end()});
  const int count = static_cast<int>(maps.size());
  const int stride = std::max(count, static_cast<int>(kLanes));
  std::vector<float> coefficients(6 * static_cast<std::size_t>(stride), 0.0f);
  std::vector<float> cumulative(static_cast<std::size_t>(count), 0.0f);
  double sum = 0;
  for (int n = 0; n < count; ++n) {
    const AffineMap& m = maps[static_cast<std::size_t>(n)];
    int k = 0;
    for (double v : {m.a, m.b, m.c, m.d, m.e, m.f})
      coefficients[static_cast<std::size_t>(k++ * stride + n)] = static_cast<float>(v);
    cumulative[static_cast<std::size_t>(n)] =
        static_cast<float>(sum += p[static_cast<std::size_t>(n)]);
  }
  const detail::PlayInput in{.draws = draws_.data(),
                             .steps = draws_.size() / kLanes,
                             .burn_in = kBurnIn,
                             .coefficients = coefficients.data(),
                             .stride = stride,
                             .count = count,
                             .cumulative = cumulative.data(),
                             .cells = cells_.data(),
                             .side = side_,
                             .size = static_cast<float>(size_),
                             .pad = static_cast<float>(pad_),
                             .hits = hits ? hits->data() : nullptr};
  return detail::play_function(level_)(in);
}

AttractorTerms AttractorLoss::terms(std::span<const AffineMap> maps) const {
  if (maps.empty()) throw Error(ErrorKind::invalid_argument, "attractor loss: no maps (got 0)");
  std::vector<std::uint8_t> hits(static_cast<std::size_t>(side_ * side_) + 1, 0);
  const double spill = play(maps, &hits);
  AttractorTerms t;
  const double points = static_cast<double>(draws_.size() - kLanes * kBurnIn);
  t.spill = spill / points / size_;
  long hit = 0, both = 0;
  cv::Rect box = bounds_;  // L's pixels and A's, on the canvas
  for (int r = 0; r < side_; ++r) {
    const std::uint8_t* row = hits.data() + static_cast<std::size_t>(r) * side_;
    long in_row = 0;
    for (int c = 0; c < side_; ++c) in_row += row[c];
    if (in_row == 0) continue;
    hit += in_row;
    int first = 0, last = side_ - 1;
    while (!row[first]) ++first;
    while (!row[last]) --last;
    box |= cv::Rect(first, r, last - first + 1, 1);
  }
  for (int i : inside_) both += hits[static_cast<std::size_t>(i)];
  const auto inside = static_cast<long>(inside_.size());
  t.iou = static_cast<double>(both) / static_cast<double>(inside + hit - both);
  // Coverage: how far L's pixels are from the nearest pixel A hits (zeros of `empty`). The
  // distance transform runs on the box around L and A only: a 3×3 chamfer distance is a sum of
  // integer steps (OpenCV's fixed point) along a path that can stay in the box of its two ends,
  // so the distances there are the whole canvas's, bit for bit, at a fraction of the pixels
  // (the canvas reaches a quarter of the square past it on every side).
  if (hit > 0) {
    cv::Mat empty(box.height, box.width, CV_8UC1), far;
    for (int r = 0; r < box.height; ++r) {
      const std::uint8_t* row = hits.data() + static_cast<std::size_t>(r + box.y) * side_ + box.x;
      auto* out = empty.ptr<std::uint8_t>(r);
      for (int c = 0; c < box.width; ++c) out[c] = row[c] ? 0 : 255;
    }
    cv::distanceTransform(empty, far, cv::DIST_L2, cv::DIST_MASK_3);
    double sum = 0;
    for (const cv::Point& p : inside_at_) sum += far.ptr<float>(p.y - box.y)[p.x - box.x];
    t.coverage = sum / static_cast<double>(inside) / size_;
  } else {
    t.coverage = 1;
  }
  double s = 0;
  for (const AffineMap& m : maps) s = std::max(s, m.contraction());
  t.contraction = s;
  const double excess = std::max(0.0, s - options_.soft_factor);
  t.value = (1 - t.iou) + options_.spill * t.spill + options_.coverage * t.coverage +
            options_.contraction * excess * excess;
  return t;
}

cv::Mat AttractorLoss::raster(std::span<const AffineMap> maps) const {
  std::vector<std::uint8_t> hits(static_cast<std::size_t>(side_ * side_) + 1, 0);
  play(maps, &hits);
  cv::Mat out(size_, size_, CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < size_; ++r)
    for (int c = 0; c < size_; ++c)
      if (hits[static_cast<std::size_t>((r + pad_) * side_ + c + pad_)])
        out.at<std::uint8_t>(r, c) = 255;
  return out;
}

}  // namespace ifsfx::collage
