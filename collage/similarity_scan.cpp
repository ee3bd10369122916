// SPDX-License-Identifier: Apache-2.0
#include "collage/similarity_scan.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "collage/similarity_polish.h"
#include "collage/target.h"
#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::collage {

namespace {

// A linear part of the grid: s · R(θ) · diag(1, a) · R(φ) · F^r on the IFS plane.
struct LinearPart {
  double s = 1, theta = 0, a = 1, phi = 0;
  bool reflected = false;
  int family = 0;  // one per scale and anisotropy: each gets its share of the candidates

  AffineMap matrix() const {
    const double ct = std::cos(theta), st = std::sin(theta);
    const double cp = std::cos(phi), sp = std::sin(phi);
    // R(θ) · diag(s, s a) · R(φ), then the reflection diag(1, −1) on the right.
    AffineMap m{ct * s * cp - st * s * a * sp, -ct * s * sp - st * s * a * cp,
                st * s * cp + ct * s * a * sp, -st * s * sp + ct * s * a * cp};
    if (reflected) m.b = -m.b, m.d = -m.d;
    return m;
  }
};

double scale_at(const SimilarityScanOptions& o, int i, int count) {
  if (count < 2) return o.max_scale;
  return o.min_scale * std::pow(o.max_scale / o.min_scale, static_cast<double>(i) / (count - 1));
}

// The grid, similarities first. Thin anisotropies (a < 0.2) draw a stalk, whose reflection is
// the same stalk: they are tried unreflected only.
std::vector<LinearPart> grid(const SimilarityScanOptions& o) {
  std::vector<LinearPart> parts;
  const double turn = 2 * std::numbers::pi;
  for (int i = 0; i < o.scales; ++i)
    for (int j = 0; j < o.angles; ++j)
      for (bool r : {false, true})
        parts.push_back({scale_at(o, i, o.scales), turn * j / o.angles, 1, 0, r, i});
  const int scales = (o.scales + 1) / 2, angles = std::max(1, o.angles / 2);
  int family = o.scales;
  for (double a : o.anisotropies)
    for (int i = 0; i < scales; ++i, ++family)
      for (int j = 0; j < angles; ++j)
        for (int k = 0; k < o.skews; ++k)
          for (bool r : {false, true})
            if (!r || a >= 0.2)
              parts.push_back({scale_at(o, i, scales), turn * j / angles, a, turn / 2 * k / o.skews,
                               r, family});
  return parts;
}

void check(const cv::Mat& target, const SimilarityScanOptions& o) {
  if (target.type() != CV_8UC1 || target.rows != target.cols || target.empty())
    throw Error(ErrorKind::invalid_argument,
                "similarity scan: the target must be a square CV_8UC1 raster");
  if (o.size < 8 || o.size > target.cols || o.scales < 1 || o.angles < 1 || o.skews < 1 ||
      o.peaks < 1 || o.keep < 1 || o.candidates < 1 || o.fine_size < o.size || o.samples < 1 ||
      o.polish_evaluations < 1 || !(o.min_scale > 0 && o.min_scale <= o.max_scale) ||
      !(o.max_scale < 1))
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("similarity scan: needs 8 ≤ size ≤ the target's side, scales, angles, "
                    "skews, peaks, keep, candidates, samples, polish_evaluations ≥ 1, fine_size ≥ "
                    "size and 0 < min_scale ≤ max_scale < 1 (got size "
                    "{}, side {}, scales {}..{})",
                    o.size, target.cols, o.min_scale, o.max_scale));
  for (double a : o.anisotropies)
    if (!(a > 0 && a < 1))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("similarity scan: anisotropies must be in (0, 1) (got {})", a));
}

// What every linear part is matched against, on the scan's raster (pixel coordinates: column,
// row, rows down).
struct Scene {
  int size = 0;
  int pad = 0;                      // Dpad reaches this many pixels beyond the raster
  cv::Mat inside;                   // L, CV_8UC1 0/255
  cv::Mat grown_padded;             // L grown by a pixel, CV_32FC1 0/1, padded by `pad`
  std::vector<cv::Point2d> points;  // 2×2 samples of every pixel of L, less the centroid
  cv::Point2d centroid;             // c, pixels
  double radius = 0;                // L's RMS distance from c, pixels
  double area = 0;                  // |L|, pixels

  Point plane_centroid() const {  // c on the IFS plane
    return {(centroid.x + 0.5) / size, 1 - (centroid.y + 0.5) / size};
  }
};

Scene scene(const cv::Mat& target, int size) {
  Scene sc;
  sc.size = size;
  sc.inside = resampled_mask(target, size);
  sc.area = cv::countNonZero(sc.inside);
  if (sc.area == 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("similarity scan: the target vanishes at size {}", size));
  cv::Mat grown;
  cv::dilate(sc.inside, grown, cv::Mat::ones(3, 3, CV_8UC1));
  // A copy may leave L by a tenth of itself and still pass min_precision ≥ 0.9.
  sc.pad = size / 10 + 1;
  grown.convertTo(grown, CV_32FC1, 1.0 / 255);
  cv::copyMakeBorder(grown, sc.grown_padded, sc.pad, sc.pad, sc.pad, sc.pad, cv::BORDER_CONSTANT,
                     0);
  double sx = 0, sy = 0;
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c)
      if (sc.inside.at<std::uint8_t>(r, c)) sx += c, sy += r;
  sc.centroid = {sx / sc.area, sy / sc.area};
  double spread = 0;
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c)
      if (sc.inside.at<std::uint8_t>(r, c)) {
        const cv::Point2d q{c - sc.centroid.x, r - sc.centroid.y};
        spread += q.dot(q);
        for (double dy : {-0.25, 0.25})
          for (double dx : {-0.25, 0.25}) sc.points.push_back({q.x + dx, q.y + dy});
      }
  sc.radius = std::sqrt(spread / sc.area);
  return sc;
}

// A copy as found on the raster, before it is written on the plane.
struct Found {
  std::size_t part = 0;
  cv::Point2d shift;  // t, pixels
  double hits = 0, drawn = 0;
  double value = 0;  // what ranks the copies (kernel())
};

// The copy A(L) about c on the raster, with a border of kRing + 1 pixels, (CV_32FC1 0/1) and
// the position of its top-left pixel relative to c rounded (pixels).
constexpr int kRing = 2;
struct Template {
  cv::Mat image;
  cv::Point origin;
};

Template draw(const Scene& sc, const AffineMap& plane) {
  // The raster's rows go down: the linear part in pixels is F A F, F = diag(1, −1).
  const double a = plane.a, b = -plane.b, c = -plane.c, d = plane.d;
  std::vector<cv::Point> at;
  at.reserve(sc.points.size());
  cv::Point lo{1 << 20, 1 << 20}, hi{-(1 << 20), -(1 << 20)};
  for (const cv::Point2d& q : sc.points) {
    const cv::Point p{static_cast<int>(std::floor(a * q.x + b * q.y + sc.centroid.x + 0.5)),
                      static_cast<int>(std::floor(c * q.x + d * q.y + sc.centroid.y + 0.5))};
    at.push_back(p);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const int border = kRing + 1;
  lo -= cv::Point(border, border);
  hi += cv::Point(border, border);
  Template t{cv::Mat(hi.y - lo.y + 1, hi.x - lo.x + 1, CV_32FC1, cv::Scalar(0)), lo};
  for (const cv::Point& p : at) t.image.at<float>(p.y - lo.y, p.x - lo.x) = 1;
  return t;
}

// The kernel that ranks translations: for a copy T, (1 + 4) · T − μ · ring(T), the ring the
// pixels kRing from T (chessboard): correlated with L grown by a pixel it gives the pixels of
// the copy in L, less 4 per pixel outside, less μ per pixel of the ring in L. The ring tells a
// copy that is a part of L — a leaflet of a fern, its edge L's edge — from one that merely lies
// inside a solid region, where every small copy fits everywhere.
cv::Mat kernel(const cv::Mat& copy, double ring_weight) {
  cv::Mat inner, outer;
  cv::dilate(copy, inner, cv::Mat::ones(2 * kRing - 1, 2 * kRing - 1, CV_8UC1));
  cv::dilate(copy, outer, cv::Mat::ones(2 * kRing + 1, 2 * kRing + 1, CV_8UC1));
  return 5 * copy - ring_weight * (outer - inner);
}

// |T ∩ L₁| with T's top-left pixel at `at` of the padded raster.
double inside(const cv::Mat& padded, const cv::Mat& copy, cv::Point at) {
  const cv::Mat under = padded(cv::Rect(at, copy.size()));
  return copy.dot(under);
}

// The best few translations of one linear part: the maxima of the kernel's correlation whose
// precision is as asked, each suppressing its neighbourhood (a sixth of the copy's size).
std::vector<Found> match(const Scene& sc, std::size_t part, const AffineMap& plane,
                         const SimilarityScanOptions& o) {
  const Template t = draw(sc, plane);
  const cv::Mat& padded = sc.grown_padded;
  if (t.image.cols > padded.cols || t.image.rows > padded.rows) return {};
  const double drawn = cv::countNonZero(t.image);
  cv::Mat score;
  cv::matchTemplate(padded, kernel(t.image, o.ring_weight), score, cv::TM_CCORR);
  const int radius = std::max(2, std::max(t.image.cols, t.image.rows) / 6);
  std::vector<Found> out;
  for (int tries = 0; tries < 4 * o.peaks && std::ssize(out) < o.peaks; ++tries) {
    double best = 0;
    cv::Point at;
    cv::minMaxLoc(score, nullptr, &best, nullptr, &at);
    if (best <= 0) break;
    const double hits = std::min(std::round(inside(padded, t.image, at)), drawn);
    if (hits >= o.min_precision * drawn - 0.5)
      // score(y, x) puts the template's top-left pixel at (x, y) − pad on the raster.
      out.push_back({part,
                     {static_cast<double>(at.x - sc.pad - t.origin.x),
                      static_cast<double>(at.y - sc.pad - t.origin.y)},
                     hits,
                     drawn,
                     best - 4 * drawn});
    const cv::Rect near(at.x - radius, at.y - radius, 2 * radius + 1, 2 * radius + 1);
    score(near & cv::Rect(0, 0, score.cols, score.rows)).setTo(-1);
  }
  return out;
}

// w on the plane: A about c, moved by `shift` pixels (rows down, the plane's y up).
AffineMap on_plane(const Scene& sc, const AffineMap& linear, cv::Point2d shift) {
  const double r = sc.size;
  const Point c = sc.plane_centroid();
  const Point t{shift.x / r, -shift.y / r};
  AffineMap w = linear;
  w.e = c.x + t.x - (w.a * c.x + w.b * c.y);
  w.f = c.y + t.y - (w.c * c.x + w.d * c.y);
  return w;
}

}  // namespace

int linear_part_count(const SimilarityScanOptions& options) {
  return static_cast<int>(grid(options).size());
}

namespace {

// The coarse scan's copies, largest first, one of each near group (at most options.candidates).
std::vector<AffineMap> coarse_copies(const Scene& sc, const SimilarityScanOptions& options) {
  const std::vector<LinearPart> parts = grid(options);
  std::vector<std::vector<Found>> per_part(parts.size());
  parallel_for(parts.size(), options.threads, [&](std::size_t k, int) {
    options.cancel.check("similarity scan");
    if (std::chrono::steady_clock::now() >= options.deadline) return;
    per_part[k] = match(sc, k, parts[k].matrix(), options);
  });
  std::vector<Found> found;
  for (const auto& v : per_part) found.insert(found.end(), v.begin(), v.end());
  // Largest first; ties in the grid's order, so the thread count never matters.
  std::stable_sort(found.begin(), found.end(),
                   [](const Found& x, const Found& y) { return x.value > y.value; });
  std::vector<AffineMap> maps;
  for (const Found& f : found) maps.push_back(on_plane(sc, parts[f.part].matrix(), f.shift));
  // Two copies closer than 2.5 pixels at L's RMS radius are one: about a grid step of θ there.
  // Each family (a scale, an anisotropy) keeps its share of the candidates, so that the many
  // large copies do not crowd out a fern's small leaflets and its stalk.
  const double r = sc.size;
  const int families = parts.back().family + 1;
  const int share = std::max(1, options.candidates / families);
  std::vector<int> taken(static_cast<std::size_t>(families), 0);
  std::vector<AffineMap> out;
  for (std::size_t i :
       detail::distinct(maps, sc.plane_centroid(), sc.radius / r, 2.5 / r, maps.size())) {
    int& count = taken[static_cast<std::size_t>(parts[found[i].part].family)];
    if (count < share) ++count, out.push_back(maps[i]);
  }
  return out;
}

}  // namespace

long scan_cost(const SimilarityScanOptions& options) {
  const double polish = static_cast<double>(options.candidates) * options.polish_evaluations *
                        options.samples / 25000;
  return linear_part_count(options) + static_cast<long>(polish);
}

std::vector<SelfCopy> scan_self_similarity(const cv::Mat& target,
                                           const SimilarityScanOptions& options) {
  check(target, options);
  const Scene sc = scene(target, options.size);
  const std::vector<AffineMap> coarse = coarse_copies(sc, options);
  // On 128² first, where a copy a few pixels off still keeps most of its points in L, then on
  // the fine raster, where only the true copies do.
  const int fine_size = std::min(options.fine_size, target.cols);
  const detail::FineScene middle(resampled_mask(target, std::min(128, fine_size)), options.samples);
  const detail::FineScene fine(resampled_mask(target, fine_size), options.samples);
  const Point c = sc.plane_centroid();
  const double bound = options.max_scale + 0.03;
  const int steps = options.polish_evaluations / 2;
  std::vector<detail::Polished> polished(coarse.size());
  parallel_for(coarse.size(), options.threads, [&](std::size_t k, int) {
    options.cancel.check("similarity scan");
    const detail::Polished first = detail::polish(middle, coarse[k], c, bound, steps);
    polished[k] = detail::polish(fine, first.map, c, bound, steps);
  });
  std::erase_if(polished, [&](const auto& p) { return p.precision < options.fine_precision; });
  std::stable_sort(polished.begin(), polished.end(),
                   [](const auto& x, const auto& y) { return x.value > y.value; });
  std::vector<AffineMap> maps;
  for (const auto& p : polished) maps.push_back(p.map);
  std::vector<SelfCopy> kept;
  // Polished copies of one true copy meet within a pixel or two of the fine raster.
  for (std::size_t i : detail::distinct(maps, sc.plane_centroid(), sc.radius / sc.size,
                                        2.0 / fine.size(), static_cast<std::size_t>(options.keep)))
    kept.push_back({maps[i], polished[i].precision, std::abs(maps[i].det())});
  return kept;
}

}  // namespace ifsfx::collage
