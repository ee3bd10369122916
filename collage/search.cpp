// SPDX-License-Identifier: Apache-2.0
#include "collage/search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include <fmt/format.h>

#include "collage/collage.h"
#include "collage/distance.h"
#include "ifs/error.h"
#include "ifs/parallel.h"
#include "ifs/rng.h"

namespace ifsfx::collage {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Pixel centres of `mask` (continuous pixel coordinates) in a fixed pseudo-random order, so that
// any prefix is an even sample of the set. The order depends on the mask only.
std::vector<Point> shuffled_centres(const cv::Mat& mask, std::uint64_t stream) {
  std::vector<Point> pts;
  for (int r = 0; r < mask.rows; ++r) {
    const auto* row = mask.ptr<std::uint8_t>(r);
    for (int c = 0; c < mask.cols; ++c)
      if (row[c]) pts.push_back({c + 0.5, r + 0.5});
  }
  Rng rng(stream_seed(0x736561726368ULL, stream));
  for (std::size_t i = pts.size(); i > 1; --i)  // Fisher–Yates
    std::swap(pts[i - 1], pts[rng.below(static_cast<std::uint32_t>(i))]);
  return pts;
}

Point centroid(const std::vector<Point>& pts) {
  Point m;
  for (const auto& p : pts) m.x += p.x, m.y += p.y;
  const auto n = static_cast<double>(pts.size());
  return {m.x / n, m.y / n};
}

// d(q, set) at the pixel nearest to q (pixels): the distance transform's value there, plus how
// far q lies outside the raster. 0 exactly on the set's pixels.
inline double nearest_distance(const cv::Mat& distance, double qx, double qy) {
  const int n = distance.cols;
  const double cx = std::clamp(qx, 0.0, n - 1e-9), cy = std::clamp(qy, 0.0, n - 1e-9);
  return distance.at<float>(static_cast<int>(cy), static_cast<int>(cx)) + std::abs(qx - cx) +
         std::abs(qy - cy);
}

// The score of search.h for one piece, in pixel coordinates: `coarse` looks the distances up at
// the nearest pixel over the first `samples` points, otherwise bilinearly over all kept points.
class PieceScorer {
 public:
  PieceScorer(const cv::Mat& distance_l, const std::vector<Point>& l_points, const cv::Mat& piece,
              const std::vector<Point>& p_points, int samples, int polish_samples, double weight)
      : distance_l_(distance_l),
        distance_p_(distance_to(piece)),
        l_area_(static_cast<double>(l_points.size())),
        p_area_(static_cast<double>(p_points.size())),
        weight_(weight) {
    l_points_.assign(
        l_points.begin(),
        l_points.begin() + std::min<std::ptrdiff_t>(polish_samples, std::ssize(l_points)));
    p_points_.assign(
        p_points.begin(),
        p_points.begin() + std::min<std::ptrdiff_t>(polish_samples, std::ssize(p_points)));
    coarse_l_ = std::min<std::size_t>(static_cast<std::size_t>(samples), l_points_.size());
    coarse_p_ = std::min<std::size_t>(static_cast<std::size_t>(samples), p_points_.size());
  }

  // `m` maps L's pixel coordinates to the piece's (the plane map seen on the raster).
  double operator()(const AffineMap& m, bool coarse) const {
    const auto inverse = m.inverse();
    if (!inverse) return kInfinity;
    const auto lookup = coarse ? &nearest_distance : &interpolated_distance;
    const std::size_t nl = coarse ? coarse_l_ : l_points_.size();
    const std::size_t np = coarse ? coarse_p_ : p_points_.size();
    // f(L) against L and P: how much of it leaves L, how much lands on other pieces, how far.
    double spill = 0, elsewhere = 0, forward = 0;
    for (std::size_t i = 0; i < nl; ++i) {
      const Point q = m(l_points_[i]);
      const double d = lookup(distance_l_, q.x, q.y);
      forward += d;
      if (d >= 0.5)
        spill += 1;
      else if (lookup(distance_p_, q.x, q.y) >= 0.5)
        elsewhere += 1;
    }
    // P against f(L): q ∈ f(L) exactly when f⁻¹(q) ∈ L.
    double missed = 0, backward = 0;
    for (std::size_t i = 0; i < np; ++i) {
      const Point p = (*inverse)(p_points_[i]);
      const double d = lookup(distance_l_, p.x, p.y);
      backward += d;
      missed += d >= 0.5;
    }
    const double image_area = std::abs(m.det()) * l_area_;
    const double wrong_area = missed / static_cast<double>(np) * p_area_ +
                              (spill + weight_ * elsewhere) / static_cast<double>(nl) * image_area;
    const double distance = forward / static_cast<double>(nl) +
                            std::sqrt(std::abs(m.det())) * backward / static_cast<double>(np);
    return wrong_area / p_area_ + kDistanceWeight * distance;
  }

 private:
  static constexpr double kDistanceWeight = 0.05;  // per pixel of mean distance
  const cv::Mat& distance_l_;
  cv::Mat distance_p_;
  double l_area_, p_area_;
  std::vector<Point> l_points_, p_points_;
  std::size_t coarse_l_ = 0, coarse_p_ = 0;
  double weight_;
};

// The searched family, in pixel coordinates: the linear part R(θ) F diag(sx, sy) K and the
// translation that sends L's centroid to the piece's centroid plus (tx, ty) pixels.
struct Pose {
  double theta = 0, log_sx = 0, log_sy = 0, shear = 0, tx = 0, ty = 0;
  bool mirror = false;

  AffineMap map(Point from, Point to) const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double sx = std::exp(log_sx), sy = std::exp(log_sy) * (mirror ? -1 : 1);
    // diag(sx, sy) K = [[sx, sx k], [0, sy]], then the rotation.
    const double m00 = sx, m01 = sx * shear, m11 = sy;
    AffineMap f{c * m00, c * m01 - s * m11, s * m00, s * m01 + c * m11, 0, 0};
    f.e = to.x + tx - (f.a * from.x + f.b * from.y);
    f.f = to.y + ty - (f.c * from.x + f.d * from.y);
    return f;
  }
};

struct Scored {
  Pose pose;
  double score = kInfinity;
  int angle = 0, i = 0, j = 0;  // grid indices, for keeping coarse winners apart
};

constexpr double kHalfLog2 = 0.5 * std::numbers::ln2;

bool by_score(const Scored& a, const Scored& b) {
  return a.score < b.score;
}

// Every pose of the coarse grid (angles, reflections, scales within a factor 4 of the piece's
// area, shears) that contracts enough, scored coarsely, best first.
std::vector<Scored> coarse_grid(const PieceScorer& scorer, Point mu_l, Point mu_p,
                                double area_ratio, const SearchOptions& o) {
  // Pixel coordinates flip y; a map's contraction and |det| are the same in both frames.
  const double log_a = 0.5 * std::log(area_ratio);
  std::vector<Scored> coarse;
  for (int t = 0; t < o.angles; ++t) {
    o.cancel.check("fit");
    if (t > 0 && std::chrono::steady_clock::now() >= o.deadline) break;
    const double theta = 2 * std::numbers::pi * t / o.angles;
    for (int mirror = 0; mirror < 2; ++mirror)
      for (int i = -o.scale_steps; i <= o.scale_steps; ++i)
        for (int j = -o.scale_steps; j <= o.scale_steps; ++j) {
          if (std::abs(i + j) > 4) continue;  // areas within a factor 4 of the piece's
          for (int k = 0; k < o.shears; ++k) {
            Scored c;
            c.pose = {theta,
                      log_a + i * kHalfLog2,
                      log_a + j * kHalfLog2,
                      o.shears > 1 ? -0.5 + static_cast<double>(k) / (o.shears - 1) : 0.0,
                      0,
                      0,
                      mirror == 1};
            const AffineMap m = c.pose.map(mu_l, mu_p);
            if (!(m.contraction() < o.max_factor)) continue;
            c.score = scorer(m, true);
            c.angle = t, c.i = i, c.j = j;
            coarse.push_back(c);
          }
        }
  }
  std::stable_sort(coarse.begin(), coarse.end(), by_score);
  return coarse;
}

// Coarse winners, kept apart: no two with the same reflection within one grid step of angle
// and scales.
std::vector<Scored> winners_apart(const std::vector<Scored>& coarse, const SearchOptions& o) {
  std::vector<Scored> winners;
  for (const auto& c : coarse) {
    if (std::ssize(winners) >= o.polished) break;
    const bool near = std::any_of(winners.begin(), winners.end(), [&](const Scored& w) {
      const int da = std::abs(w.angle - c.angle);
      return w.pose.mirror == c.pose.mirror && std::min(da, o.angles - da) <= 1 &&
             std::abs(w.i - c.i) <= 1 && std::abs(w.j - c.j) <= 1;
    });
    if (!near) winners.push_back(c);
  }
  return winners;
}

// Compass search from each winner over (θ, ln sx, ln sy, k, tx, ty), on the smooth score; best
// first after.
void polish_winners(const PieceScorer& scorer, Point mu_l, Point mu_p, const SearchOptions& o,
                    std::vector<Scored>& winners) {
  const double angle_step = std::numbers::pi / std::max(o.angles, 1);
  for (auto& w : winners) {
    if (std::chrono::steady_clock::now() >= o.deadline) break;  // the rest keep coarse scores
    std::array<double, 6> step = {angle_step, kHalfLog2 / 2, kHalfLog2 / 2, 0.125, 1.0, 1.0};
    w.score = scorer(w.pose.map(mu_l, mu_p), false);
    for (int halvings = 0, evaluations = 0; halvings < 5 && evaluations < 240;) {
      o.cancel.check("fit");
      bool improved = false;
      for (int d = 0; d < 6; ++d)
        for (int sign : {1, -1}) {
          Pose trial = w.pose;
          double* field[] = {&trial.theta, &trial.log_sx, &trial.log_sy,
                             &trial.shear, &trial.tx,     &trial.ty};
          *field[d] += sign * step[static_cast<std::size_t>(d)];
          const AffineMap m = trial.map(mu_l, mu_p);
          ++evaluations;
          if (!(m.contraction() < o.max_factor)) continue;
          const double value = scorer(m, false);
          if (value < w.score) {
            w.score = value;
            w.pose = trial;
            improved = true;
            break;
          }
        }
      if (!improved) {
        for (auto& s : step) s *= 0.5;
        ++halvings;
      }
    }
  }
  std::stable_sort(winners.begin(), winners.end(), by_score);
}

// The best distinct maps for one piece.
std::vector<Candidate> search_piece(const PieceScorer& scorer, Point mu_l, Point mu_p,
                                    double area_ratio, int size, const SearchOptions& o) {
  const AffineMap to_pixel = plane_to_pixel(size);
  const AffineMap to_plane = *to_pixel.inverse();
  std::vector<Scored> winners = winners_apart(coarse_grid(scorer, mu_l, mu_p, area_ratio, o), o);
  polish_winners(scorer, mu_l, mu_p, o, winners);

  // Distinct maps: polishing may bring two winners to the same place.
  std::vector<Candidate> kept;
  for (const auto& w : winners) {
    if (std::ssize(kept) >= o.keep) break;
    const AffineMap f = to_plane.compose(w.pose.map(mu_l, mu_p).compose(to_pixel));
    const bool same = std::any_of(kept.begin(), kept.end(), [&](const Candidate& c) {
      const auto a = c.map.coefficients(), b = f.coefficients();
      for (std::size_t i = 0; i < 6; ++i)
        if (std::abs(a[i] - b[i]) > (i < 4 ? 0.03 : 1.5 / size)) return false;
      return true;
    });
    if (!same) kept.push_back({f, w.score});
  }
  return kept;
}

void check(const cv::Mat& target, const cv::Mat& labels, int n, const SearchOptions& o) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "search: the target must be a non-empty square CV_8UC1 working raster");
  if (labels.type() != CV_32SC1 || labels.size() != target.size())
    throw Error(ErrorKind::invalid_argument,
                "search: the labels must be CV_32SC1 of the target's size");
  if (n < 1)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("search: the number of pieces must be ≥ 1 (got {})", n));
  if (o.angles < 1 || o.scale_steps < 0 || o.shears < 1 || o.samples < 1 || o.polish_samples < 1 ||
      o.polished < 1 || o.keep < 1 || !(o.max_factor > 0))
    throw Error(ErrorKind::invalid_argument,
                "search: angles, shears, samples, polished and keep must be ≥ 1, scale_steps ≥ 0 "
                "and max_factor > 0");
}

}  // namespace

std::vector<std::vector<Candidate>> search_pieces(const cv::Mat& target, const cv::Mat& labels,
                                                  int n, const SearchOptions& options) {
  check(target, labels, n, options);
  const int size = target.cols;
  const cv::Mat distance_l = distance_to(target);
  const std::vector<Point> l_points = shuffled_centres(target, 0);
  const Point mu_l = centroid(l_points);
  const double l_area = static_cast<double>(l_points.size());

  std::vector<std::vector<Candidate>> found(static_cast<std::size_t>(n));
  parallel_for(static_cast<std::size_t>(n), options.threads, [&](std::size_t k, int) {
    const cv::Mat piece = labels == static_cast<int>(k);
    const int area = cv::countNonZero(piece);
    if (area == 0) {  // a small copy of L at its centroid keeps N maps
      const AffineMap to_plane = *plane_to_pixel(size).inverse();
      const Point c = to_plane(mu_l);
      found[k] = {{{0.25, 0, 0, 0.25, 0.75 * c.x, 0.75 * c.y}, kInfinity}};
      return;
    }
    const std::vector<Point> p_points = shuffled_centres(piece, 1);
    const PieceScorer scorer(distance_l, l_points, piece, p_points, options.samples,
                             options.polish_samples, options.piece_weight);
    found[k] = search_piece(scorer, mu_l, centroid(p_points), area / l_area, size, options);
  });
  return found;
}

double piece_score(const cv::Mat& target, const cv::Mat& piece, const AffineMap& f, int samples,
                   double piece_weight) {
  if (target.type() != CV_8UC1 || piece.type() != CV_8UC1 || piece.size() != target.size() ||
      cv::countNonZero(piece) == 0 || cv::countNonZero(target) == 0)
    throw Error(ErrorKind::invalid_argument,
                "search: target and piece must be non-empty CV_8UC1 masks of one size");
  const cv::Mat distance_l = distance_to(target);
  const PieceScorer scorer(distance_l, shuffled_centres(target, 0), piece,
                           shuffled_centres(piece, 1), samples, samples, piece_weight);
  const AffineMap to_pixel = plane_to_pixel(target.cols);
  return scorer(to_pixel.compose(f.compose(*to_pixel.inverse())), false);
}

}  // namespace ifsfx::collage
