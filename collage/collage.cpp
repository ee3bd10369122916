// SPDX-License-Identifier: Apache-2.0
#include "collage/collage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "collage/distance.h"
#include "ifs/error.h"

namespace ifsfx::collage {

namespace {

void check_target(const cv::Mat& target) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || target.empty())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("collage: the target must be a square CV_8UC1 working raster (got "
                            "{}×{}, type {})",
                            target.cols, target.rows, target.type()));
  if (cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument, "collage: the target is empty (no pixel is set)");
}

void check_maps(std::span<const AffineMap> maps) {
  if (maps.empty())
    throw Error(ErrorKind::invalid_argument, "collage: at least one map is needed (got 0)");
  for (std::size_t i = 0; i < maps.size(); ++i)
    if (!maps[i].finite())
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("collage: map {}: coefficients must be finite (got NaN or inf)", i + 1));
}

// f in the raster's continuous pixel coordinates: P ∘ f ∘ P⁻¹.
AffineMap pixel_map(const AffineMap& f, int size) {
  const AffineMap to_pixel = plane_to_pixel(size);
  const AffineMap to_plane = *to_pixel.inverse();
  return to_pixel.compose(f.compose(to_plane));
}

std::vector<cv::Point2f> centres_of(const cv::Mat& mask) {
  std::vector<cv::Point2f> points;
  for (int r = 0; r < mask.rows; ++r) {
    const auto* row = mask.ptr<std::uint8_t>(r);
    for (int c = 0; c < mask.cols; ++c)
      if (row[c]) points.emplace_back(static_cast<float>(c) + 0.5f, static_cast<float>(r) + 0.5f);
  }
  return points;
}

}  // namespace

AffineMap plane_to_pixel(int size) {
  const double s = size;
  return {s, 0, 0, -s, 0, s};
}

cv::Mat collage_raster(const cv::Mat& target, std::span<const AffineMap> maps, int subsamples) {
  check_target(target);
  check_maps(maps);
  if (subsamples < 1 || subsamples > 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("collage: subsamples must be in 1..16 (got {})", subsamples));
  const int n = target.cols;
  cv::Mat w(n, n, CV_8UC1, cv::Scalar(0));
  const auto points = centres_of(target);
  const double step = 1.0 / subsamples;
  for (const auto& f : maps) {
    const AffineMap m = pixel_map(f, n);
    for (const auto& p : points)
      for (int j = 0; j < subsamples; ++j)
        for (int i = 0; i < subsamples; ++i) {
          const Point q = m({p.x - 0.5 + (i + 0.5) * step, p.y - 0.5 + (j + 0.5) * step});
          const double c = std::floor(q.x), r = std::floor(q.y);
          if (c >= 0 && r >= 0 && c < n && r < n)
            w.at<std::uint8_t>(static_cast<int>(r), static_cast<int>(c)) = 255;
        }
  }
  return w;
}

double collage_distance(const cv::Mat& target, std::span<const AffineMap> maps) {
  check_target(target);
  check_maps(maps);
  const int n = target.cols;
  const auto points = centres_of(target);
  const cv::Mat to_l = distance_to(target);

  // Direction W(L) → L: every image point's distance to L, bounded above exactly.
  // Direction L → W(L): the image points are binned to their pixel; near[pixel] keeps the
  // smallest way from a point of that pixel to the pixel's centre. For p in L with nearest
  // occupied centre g*, d(p, W(L)) ≤ |p − g*| + near[g*] ≤ EDT(p) + max near.
  double w_to_l = 0;
  cv::Mat near(n, n, CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  Point any_image{};
  for (const auto& f : maps) {
    const AffineMap m = pixel_map(f, n);
    for (const auto& p : points) {
      const Point q = m({p.x, p.y});
      any_image = q;
      w_to_l = std::max(w_to_l, distance_bound(to_l, q.x, q.y));
      const double c = std::floor(q.x), r = std::floor(q.y);
      if (c >= 0 && r >= 0 && c < n && r < n) {
        float& slot = near.at<float>(static_cast<int>(r), static_cast<int>(c));
        slot = std::min(slot, static_cast<float>(std::hypot(q.x - (c + 0.5), q.y - (r + 0.5))));
      }
    }
  }
  const cv::Mat occupied = near < std::numeric_limits<float>::infinity();
  double l_to_w = 0;
  if (cv::countNonZero(occupied) == 0) {
    // Every image point left the raster: bound d(p, W(L)) by the way to one of them.
    for (const auto& p : points)
      l_to_w = std::max(l_to_w, std::hypot(p.x - any_image.x, p.y - any_image.y));
  } else {
    double slack = 0;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (occupied.at<std::uint8_t>(r, c))
          slack = std::max(slack, static_cast<double>(near.at<float>(r, c)));
    l_to_w = directed_hausdorff(target, occupied) + slack;
  }
  return std::max(w_to_l, l_to_w) / n;
}

CollageObjective::CollageObjective(const cv::Mat& target, const ObjectiveOptions& options)
    : options_(options) {
  check_target(target);
  size_ = target.cols;
  target_ = target.clone();
  distance_ = distance_to(target_);
  points_ = centres_of(target_);
  deep_.assign(static_cast<std::size_t>(size_ - 1) * static_cast<std::size_t>(size_ - 1), 0);
  for (int r = 0; r + 1 < size_; ++r)
    for (int c = 0; c + 1 < size_; ++c)
      deep_[static_cast<std::size_t>(r) * static_cast<std::size_t>(size_ - 1) +
            static_cast<std::size_t>(c)] =
          target_.at<std::uint8_t>(r, c) && target_.at<std::uint8_t>(r, c + 1) &&
          target_.at<std::uint8_t>(r + 1, c) && target_.at<std::uint8_t>(r + 1, c + 1);
  inside_.assign((static_cast<std::size_t>(size_) * size_ + 63) / 64, 0);
  for (const auto& p : points_) {
    const std::size_t bit = static_cast<std::size_t>(p.y) * size_ + static_cast<std::size_t>(p.x);
    inside_[bit / 64] |= std::uint64_t{1} << (bit % 64);
    centroid_.x += p.x;
    centroid_.y += p.y;
  }
  const auto count = static_cast<double>(points_.size());
  centroid_ = {centroid_.x / count / size_, 1 - centroid_.y / count / size_};
}

Footprint CollageObjective::footprint(const AffineMap& f) const {
  if (!f.finite())
    throw Error(ErrorKind::invalid_argument,
                "collage: coefficients must be finite (got NaN or inf)");
  const int n = size_;
  const AffineMap m = pixel_map(f, n);
  Footprint out;
  out.hits.assign(inside_.size(), 0);
  out.det = std::abs(f.det());
  out.factor = f.contraction();
  // W(L) from L's exact pixel centres, with the spill of every image point: the distance
  // interpolated between pixel centres (interpolated_distance, inlined here for the points
  // inside the centres' square, which is nearly all of them).
  const float* d = distance_.ptr<float>(0);
  const auto stride = static_cast<std::size_t>(distance_.step1());
  const double last = n - 1;
  for (const auto& p : points_) {
    const double qx = m.a * p.x + m.b * p.y + m.e;
    const double qy = m.c * p.x + m.d * p.y + m.f;
    const double x = qx - 0.5, y = qy - 0.5;
    if (x >= 0 && y >= 0 && x < last && y < last) {
      const auto c = static_cast<std::size_t>(x), r = static_cast<std::size_t>(y);
      const std::size_t bit =
          (r + (y - static_cast<double>(r) >= 0.5)) * static_cast<std::size_t>(n) + c +
          (x - static_cast<double>(c) >= 0.5);
      out.hits[bit / 64] |= std::uint64_t{1} << (bit % 64);
      if (deep_[r * static_cast<std::size_t>(n - 1) + c]) continue;  // inside L: no spill
      const double u = x - static_cast<double>(c), v = y - static_cast<double>(r);
      const float* row0 = d + r * stride + c;
      const float* row1 = row0 + stride;
      out.spill +=
          (1 - v) * ((1 - u) * row0[0] + u * row0[1]) + v * ((1 - u) * row1[0] + u * row1[1]);
      continue;
    }
    out.spill += interpolated_distance(distance_, qx, qy);
    const double c = std::floor(qx), r = std::floor(qy);
    if (c >= 0 && r >= 0 && c < n && r < n) {
      const auto bit =
          static_cast<std::size_t>(r) * static_cast<std::size_t>(n) + static_cast<std::size_t>(c);
      out.hits[bit / 64] |= std::uint64_t{1} << (bit % 64);
    }
  }
  return out;
}

ObjectiveTerms CollageObjective::terms(std::span<const AffineMap> maps) const {
  check_maps(maps);
  std::vector<Footprint> parts;
  parts.reserve(maps.size());
  for (const auto& f : maps) parts.push_back(footprint(f));
  std::vector<const Footprint*> pointers;
  for (const auto& p : parts) pointers.push_back(&p);
  return terms(std::span<const Footprint* const>(pointers));
}

Footprint merge(std::span<const Footprint* const> parts) {
  if (parts.empty())
    throw Error(ErrorKind::invalid_argument, "collage: nothing to merge (no footprint)");
  Footprint out = *parts.front();
  for (const Footprint* p : parts.subspan(1)) {
    for (std::size_t w = 0; w < out.hits.size(); ++w) out.hits[w] |= p->hits[w];
    out.spill += p->spill;
    out.det += p->det;
    out.factor = std::max(out.factor, p->factor);
    out.maps += p->maps;
  }
  return out;
}

double CollageObjective::iterated(std::span<const AffineMap> maps, int iterations) const {
  check_maps(maps);
  if (iterations < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("collage: iterations must be ≥ 1 (got {})", iterations));
  const int n = size_;
  std::vector<AffineMap> pixel_maps;
  double factor = 0;
  for (const auto& f : maps) {
    pixel_maps.push_back(pixel_map(f, n));
    factor = std::max(factor, f.contraction());
  }
  std::vector<std::uint64_t> current = inside_, next(inside_.size());
  for (int it = 0; it < iterations; ++it) {
    std::fill(next.begin(), next.end(), 0);
    for (std::size_t w = 0; w < current.size(); ++w)
      for (std::uint64_t bits = current[w]; bits != 0; bits &= bits - 1) {
        const std::size_t bit = w * 64 + static_cast<std::size_t>(std::countr_zero(bits));
        const double px = static_cast<double>(bit % static_cast<std::size_t>(n)) + 0.5;
        const double py = static_cast<double>(bit / static_cast<std::size_t>(n)) + 0.5;
        // ⌊x⌋ ∈ [0, n) exactly when x ∈ [0, n) (n an integer), and there ⌊x⌋ is the
        // truncation: the same pixels as with std::floor, without its rounding sequence (SSE2
        // has no ROUNDSD).
        for (const auto& m : pixel_maps) {
          const double x = m.a * px + m.b * py + m.e;
          const double y = m.c * px + m.d * py + m.f;
          if (x >= 0 && y >= 0 && x < n && y < n) {
            const auto b = static_cast<std::size_t>(y) * static_cast<std::size_t>(n) +
                           static_cast<std::size_t>(x);
            next[b / 64] |= std::uint64_t{1} << (b % 64);
          }
        }
      }
    current.swap(next);
  }
  long both = 0, either = 0;
  for (std::size_t w = 0; w < current.size(); ++w) {
    both += std::popcount(current[w] & inside_[w]);
    either += std::popcount(current[w] | inside_[w]);
  }
  const double iou = either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
  return (1 - iou) + contraction_penalty(factor);
}

double CollageObjective::contraction_penalty(double factor) const {
  const ObjectiveOptions& k = options_;
  const double soft = std::max(0.0, factor - k.soft_factor);
  double penalty = k.contraction * soft * soft;
  if (factor >= k.max_factor) penalty += 1 + 10 * (factor - k.max_factor);
  return penalty;
}

ObjectiveTerms CollageObjective::terms(std::span<const Footprint* const> parts) const {
  if (parts.empty())
    throw Error(ErrorKind::invalid_argument, "collage: at least one map is needed (got 0)");
  ObjectiveTerms t;
  double dets = 0, spill = 0;
  int count = 0;
  for (const Footprint* p : parts) {
    t.contraction = std::max(t.contraction, p->factor);
    dets += p->det;
    spill += p->spill;
    count += p->maps;
  }
  // IoU(L, W(L)) from the bits: |L ∩ W| / |L ∪ W|.
  long both = 0, either = 0;
  for (std::size_t w = 0; w < inside_.size(); ++w) {
    std::uint64_t hit = 0;
    for (const Footprint* p : parts) hit |= p->hits[w];
    both += std::popcount(hit & inside_[w]);
    either += std::popcount(hit | inside_[w]);
  }
  t.collage_iou = either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
  t.spill = spill / (static_cast<double>(points_.size()) * count) / size_;
  t.overlap = std::max(0.0, dets - 1);

  t.value = (1 - t.collage_iou) + options_.spill * t.spill + options_.overlap * t.overlap +
            contraction_penalty(t.contraction);
  return t;
}

}  // namespace ifsfx::collage
