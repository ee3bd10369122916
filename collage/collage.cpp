#include "collage/collage.h"

#include <algorithm>
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

// Upper bound of d(q, L) from the distance transform of L: the distance at the pixel nearest to
// q (clamped into the raster) plus the way from q to that pixel's centre.
double distance_bound(const cv::Mat& distance, double qx, double qy) {
  const int n = distance.cols;
  const int c = std::clamp(static_cast<int>(std::floor(qx)), 0, n - 1);
  const int r = std::clamp(static_cast<int>(std::floor(qy)), 0, n - 1);
  return distance.at<float>(r, c) + std::hypot(qx - (c + 0.5), qy - (r + 0.5));
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
}

namespace {

// d(q, L) interpolated bilinearly between pixel centres (pixels): continuous in q, so the
// optimiser feels sub-pixel moves; outside the raster, the exact bound of distance_bound.
double interpolated_distance(const cv::Mat& distance, double qx, double qy) {
  const int n = distance.cols;
  const double x = qx - 0.5, y = qy - 0.5;  // centre-based coordinates
  if (!(x >= 0 && y >= 0 && x <= n - 1 && y <= n - 1)) return distance_bound(distance, qx, qy);
  const int c = std::min(static_cast<int>(x), n - 2), r = std::min(static_cast<int>(y), n - 2);
  const double u = x - c, v = y - r;
  const float* row0 = distance.ptr<float>(r);
  const float* row1 = distance.ptr<float>(r + 1);
  return (1 - v) * ((1 - u) * row0[c] + u * row0[c + 1]) +
         v * ((1 - u) * row1[c] + u * row1[c + 1]);
}

// IoU of the target with the raster `w` (0/1 bytes).
double raster_iou(const cv::Mat& target, const std::vector<std::uint8_t>& w) {
  const int n = target.cols;
  long both = 0, either = 0;
  for (int r = 0; r < n; ++r) {
    const auto* in = target.ptr<std::uint8_t>(r);
    const std::uint8_t* out = w.data() + static_cast<std::size_t>(r) * n;
    for (int c = 0; c < n; ++c) {
      both += (in[c] != 0) & (out[c] != 0);
      either += (in[c] != 0) | (out[c] != 0);
    }
  }
  return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

}  // namespace

ObjectiveTerms CollageObjective::terms(std::span<const AffineMap> maps) const {
  check_maps(maps);
  ObjectiveTerms t;
  const int n = size_;
  std::vector<AffineMap> pixel_maps;
  double dets = 0;
  for (const auto& f : maps) {
    t.contraction = std::max(t.contraction, f.contraction());
    dets += std::abs(f.det());
    pixel_maps.push_back(pixel_map(f, n));
  }

  // Level 1: W(L) from L's exact pixel centres, with the spill of every image point.
  std::vector<std::uint8_t> w(static_cast<std::size_t>(n) * n, 0);
  double spill = 0;
  for (const auto& m : pixel_maps)
    for (const auto& p : points_) {
      const double qx = m.a * p.x + m.b * p.y + m.e;
      const double qy = m.c * p.x + m.d * p.y + m.f;
      spill += interpolated_distance(distance_, qx, qy);
      const double c = std::floor(qx), r = std::floor(qy);
      if (c >= 0 && r >= 0 && c < n && r < n)
        w[static_cast<std::size_t>(r) * n + static_cast<std::size_t>(c)] = 1;
    }
  t.collage_iou = raster_iou(target_, w);
  t.spill = spill / (static_cast<double>(points_.size()) * static_cast<double>(maps.size())) / n;
  t.overlap = std::max(0.0, dets - 1);

  const ObjectiveOptions& k = options_;
  const double soft = std::max(0.0, t.contraction - k.soft_factor);
  t.value =
      (1 - t.collage_iou) + k.spill * t.spill + k.overlap * t.overlap + k.contraction * soft * soft;
  if (t.contraction >= k.max_factor) t.value += 1 + 10 * (t.contraction - k.max_factor);
  return t;
}

}  // namespace ifsfx::collage
