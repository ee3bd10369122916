// SPDX-License-Identifier: Apache-2.0
#include "collage/initialise.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/collage.h"
#include "collage/distance.h"
#include "ifs/error.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

namespace {

struct Moments {
  double count = 0;
  Point mean;
  double sxx = 0, sxy = 0, syy = 0;  // covariance
};

// A symmetric 2×2 matrix [[p q][q r]] as eigenvalues l1 ≥ l2 and the unit eigenvector of l1.
struct Eigen2 {
  double l1 = 0, l2 = 0;
  Point v1{1, 0};
};

Eigen2 eigen(double p, double q, double r) {
  Eigen2 e;
  const double h = 0.5 * (p + r);
  const double d = std::hypot(0.5 * (p - r), q);
  e.l1 = h + d;
  e.l2 = h - d;
  const Point a{q, e.l1 - p}, b{e.l1 - r, q};
  const Point v = std::hypot(a.x, a.y) >= std::hypot(b.x, b.y) ? a : b;
  const double len = std::hypot(v.x, v.y);
  e.v1 = len > 0 ? Point{v.x / len, v.y / len} : Point{1, 0};
  return e;
}

// Σ^power for a covariance Σ (power ±1/2), as the linear part of an AffineMap.
AffineMap covariance_power(const Moments& m, double power) {
  const Eigen2 e = eigen(m.sxx, m.sxy, m.syy);
  const double k1 = std::pow(e.l1, power), k2 = std::pow(e.l2, power);
  const Point u = e.v1, v{-e.v1.y, e.v1.x};
  return {k1 * u.x * u.x + k2 * v.x * v.x,
          k1 * u.x * u.y + k2 * v.x * v.y,
          k1 * u.x * u.y + k2 * v.x * v.y,
          k1 * u.y * u.y + k2 * v.y * v.y,
          0,
          0};
}

// Pixel centres of L in plane coordinates.
std::vector<Point> plane_points(const cv::Mat& target) {
  const double n = target.cols;
  std::vector<Point> pts;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) pts.push_back({(c + 0.5) / n, 1 - (r + 0.5) / n});
  return pts;
}

// Moments of the points with label `k`; each pixel is a square, so its own variance 1/(12 S²)
// is added and no part is ever degenerate.
Moments moments(const std::vector<Point>& pts, const std::vector<int>& label, int k, int size) {
  Moments m;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (label[i] == k) {
      m.count += 1;
      m.mean.x += pts[i].x;
      m.mean.y += pts[i].y;
    }
  if (m.count == 0) return m;
  m.mean.x /= m.count;
  m.mean.y /= m.count;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (label[i] == k) {
      const double dx = pts[i].x - m.mean.x, dy = pts[i].y - m.mean.y;
      m.sxx += dx * dx, m.sxy += dx * dy, m.syy += dy * dy;
    }
  const double pixel_variance = 1.0 / (12.0 * size * size);
  m.sxx = m.sxx / m.count + pixel_variance;
  m.sxy = m.sxy / m.count;
  m.syy = m.syy / m.count + pixel_variance;
  return m;
}

void split_principal_axes(const std::vector<Point>& pts, int n, int size, std::vector<int>& label) {
  std::fill(label.begin(), label.end(), 0);
  for (int parts = 1; parts < n; ++parts) {
    // The part of largest inertia (count × trace Σ): the biggest, most spread-out piece.
    int widest = 0;
    double inertia = -1;
    for (int k = 0; k < parts; ++k) {
      const Moments m = moments(pts, label, k, size);
      if (m.count < 2) continue;
      const double value = m.count * (m.sxx + m.syy);
      if (value > inertia) inertia = value, widest = k;
    }
    const Moments m = moments(pts, label, widest, size);
    const Point axis = eigen(m.sxx, m.sxy, m.syy).v1;
    std::vector<std::pair<double, std::size_t>> along;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (label[i] == widest)
        along.emplace_back((pts[i].x - m.mean.x) * axis.x + (pts[i].y - m.mean.y) * axis.y, i);
    std::sort(along.begin(), along.end());
    for (std::size_t j = along.size() / 2; j < along.size(); ++j) label[along[j].second] = parts;
  }
}

std::vector<Point> kmeans_plus_plus_seeds(const std::vector<Point>& pts, int n,
                                          std::uint64_t seed) {
  Rng rng(stream_seed(seed, 0));
  std::vector<Point> centres{pts[rng.below(static_cast<std::uint32_t>(pts.size()))]};
  std::vector<double> d2(pts.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(centres.size()) < n) {
    double total = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double dx = pts[i].x - centres.back().x, dy = pts[i].y - centres.back().y;
      d2[i] = std::min(d2[i], dx * dx + dy * dy);
      total += d2[i];
    }
    double pick = rng.uniform() * total;
    std::size_t chosen = pts.size() - 1;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      pick -= d2[i];
      if (pick < 0) {
        chosen = i;
        break;
      }
    }
    centres.push_back(pts[chosen]);
  }
  return centres;
}

void assign(const std::vector<Point>& pts, const std::vector<Point>& centres,
            std::vector<int>& label) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const double dx = pts[i].x - centres[k].x, dy = pts[i].y - centres[k].y;
      const double d = dx * dx + dy * dy;
      if (d < best) best = d, label[i] = static_cast<int>(k);
    }
  }
}

// Labels 0..n−1 of `pts` by the split and Lloyd's iterations.
std::vector<int> split_points(const std::vector<Point>& pts, int n, int size,
                              const InitOptions& options, std::uint64_t seed) {
  std::vector<int> label(pts.size(), 0);
  std::vector<Point> centres;
  if (options.split == Split::principal_axes) {
    split_principal_axes(pts, n, size, label);
    for (int k = 0; k < n; ++k) centres.push_back(moments(pts, label, k, size).mean);
  } else {
    centres = kmeans_plus_plus_seeds(pts, n, seed);
    assign(pts, centres, label);
  }
  for (int it = 0; it < options.lloyd_iterations; ++it) {
    for (int k = 0; k < n; ++k) {
      const Moments m = moments(pts, label, k, size);
      if (m.count > 0)
        centres[static_cast<std::size_t>(k)] = m.mean;  // an empty part keeps its seed
    }
    assign(pts, centres, label);
  }
  return label;
}

// Component (8-connected, 0-based, in order of first pixel) of each pixel of L, in the order of
// plane_points.
std::vector<int> component_of(const cv::Mat& target, int& count) {
  cv::Mat labels;
  count = cv::connectedComponents(target, labels, 8, CV_32S) - 1;
  std::vector<int> first_seen(static_cast<std::size_t>(count) + 1, -1);
  std::vector<int> out;
  int next = 0;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) {
        int& id = first_seen[static_cast<std::size_t>(labels.at<int>(r, c))];
        if (id < 0) id = next++;
        out.push_back(id);
      }
  return out;
}

// Parts per component: one for each component that can carry one (the largest first, at most
// n), the rest by D'Hondt's rule on the areas.
std::vector<int> allot_parts(const std::vector<long>& area, long total, int n) {
  std::vector<std::size_t> order(area.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return area[i] > area[j]; });
  std::vector<int> parts(area.size(), 0);
  int given = 0;
  for (std::size_t i : order)
    if (given < n && area[i] * 4 * n >= total) parts[i] = 1, ++given;
  if (given == 0) parts[order.front()] = 1, given = 1;  // one component holds all the parts
  for (; given < n; ++given) {
    std::size_t best = order.front();
    double quota = -1;
    for (std::size_t i : order)
      if (parts[i] > 0 && static_cast<double>(area[i]) / (parts[i] + 1) > quota)
        quota = static_cast<double>(area[i]) / (parts[i] + 1), best = i;
    ++parts[best];
  }
  return parts;
}

std::vector<int> split_by_component(const cv::Mat& target, const std::vector<Point>& pts, int n,
                                    const InitOptions& options) {
  const int size = target.cols;
  int count = 0;
  const std::vector<int> component = component_of(target, count);
  std::vector<long> area(static_cast<std::size_t>(count), 0);
  for (int c : component) ++area[static_cast<std::size_t>(c)];
  const std::vector<int> parts = allot_parts(area, static_cast<long>(pts.size()), n);

  std::vector<int> label(pts.size(), -1);
  std::vector<Point> centres;
  int first_label = 0;
  for (int c = 0; c < count; ++c) {
    std::vector<Point> own;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (component[i] == c) own.push_back(pts[i]), index.push_back(i);
    const int k = std::min(parts[static_cast<std::size_t>(c)], static_cast<int>(own.size()));
    if (k == 0) continue;
    const auto sub = split_points(own, k, size, options,
                                  stream_seed(options.seed, static_cast<std::uint64_t>(c)));
    for (std::size_t j = 0; j < own.size(); ++j) label[index[j]] = first_label + sub[j];
    for (int m = 0; m < k; ++m) centres.push_back(moments(own, sub, m, size).mean);
    first_label += k;
  }
  // Components without a part of their own join the part whose centre is nearest.
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (label[i] < 0) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < centres.size(); ++k) {
        const double d = std::hypot(pts[i].x - centres[k].x, pts[i].y - centres[k].y);
        if (d < best) best = d, label[i] = static_cast<int>(k);
      }
    }
  return label;
}

std::vector<int> labels_of(const cv::Mat& target, const std::vector<Point>& pts, int n,
                           const InitOptions& options) {
  if (options.by_component) return split_by_component(target, pts, n, options);
  return split_points(pts, n, target.cols, options, options.seed);
}

void check(const cv::Mat& target, int n) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || target.empty())
    throw Error(ErrorKind::invalid_argument,
                "initialise: the target must be a square CV_8UC1 working raster");
  const int count = cv::countNonZero(target);
  if (n < 1 || n > count)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("-n: the number of maps must be in 1..{} for this target (got {})", count, n));
}

}  // namespace

cv::Mat partition(const cv::Mat& target, int n, const InitOptions& options) {
  check(target, n);
  const auto pts = plane_points(target);
  const auto label = labels_of(target, pts, n, options);
  cv::Mat out(target.size(), CV_32SC1, cv::Scalar(-1));
  std::size_t i = 0;
  for (int r = 0; r < target.rows; ++r)
    for (int c = 0; c < target.cols; ++c)
      if (target.at<std::uint8_t>(r, c)) out.at<int>(r, c) = label[i++];
  return out;
}

std::vector<AffineMap> initial_maps(const cv::Mat& target, int n, const InitOptions& options) {
  check(target, n);
  const int size = target.cols;
  const auto pts = plane_points(target);
  const auto label = labels_of(target, pts, n, options);
  const Moments whole = moments(pts, std::vector<int>(pts.size(), 0), 0, size);
  const AffineMap whiten = covariance_power(whole, -0.5);

  std::vector<AffineMap> maps;
  for (int k = 0; k < n; ++k) {
    const Moments part = moments(pts, label, k, size);
    cv::Mat part_mask(target.size(), CV_8UC1, cv::Scalar(0));
    std::size_t i = 0;
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c)
        if (target.at<std::uint8_t>(r, c))
          part_mask.at<std::uint8_t>(r, c) = label[i++] == k ? 255 : 0;
    if (part.count == 0) {  // Lloyd emptied it: a small copy at L's centroid keeps N maps
      maps.push_back({0.25, 0, 0, 0.25, 0.75 * whole.mean.x, 0.75 * whole.mean.y});
      continue;
    }
    const AffineMap colour = covariance_power(part, 0.5);
    AffineMap best;
    double best_iou = -1;
    for (int turn = 0; turn < 8; ++turn)
      for (int mirror = 0; mirror < 2; ++mirror) {
        const double t = turn * std::numbers::pi / 4;
        const double m = mirror ? -1 : 1;
        const AffineMap rotation{std::cos(t), -std::sin(t) * m, std::sin(t), std::cos(t) * m, 0, 0};
        AffineMap f = colour.compose(rotation.compose(whiten));
        const double s = f.contraction();
        if (s >= 0.95)
          f = AffineMap{f.a * 0.9 / s, f.b * 0.9 / s, f.c * 0.9 / s, f.d * 0.9 / s, 0, 0};
        f.e = part.mean.x - (f.a * whole.mean.x + f.b * whole.mean.y);
        f.f = part.mean.y - (f.c * whole.mean.x + f.d * whole.mean.y);
        const AffineMap one[] = {f};
        const double overlap = iou(collage_raster(target, one, 1), part_mask);
        if (overlap > best_iou) best_iou = overlap, best = f;
      }
    maps.push_back(best);
  }
  return maps;
}

}  // namespace ifsfx::collage
