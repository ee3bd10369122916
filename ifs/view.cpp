// SPDX-License-Identifier: Apache-2.0
#include "ifs/view.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "ifs/chaos_game.h"
#include "ifs/detail/preconditions.h"
#include "ifs/error.h"

namespace ifsfx {

AffineMap Viewport::plane_to_pixel() const {
  const double sx = size.width / view.width();
  const double sy = size.height / view.height();
  return {sx, 0, 0, -sy, -sx * view.x0, sy * view.y1};
}

namespace {

Box bounds_by_sampling(const Ifs& ifs, std::uint64_t seed, const CancelToken& cancel) {
  const auto samples =
      chaos_game_samples(ifs, 1 << 20, {.seed = seed, .threads = 0, .cancel = cancel});
  Box b{samples[0].p.x, samples[0].p.y, samples[0].p.x, samples[0].p.y};
  for (const auto& s : samples) {
    b.x0 = std::min(b.x0, s.p.x), b.x1 = std::max(b.x1, s.p.x);
    b.y0 = std::min(b.y0, s.p.y), b.y1 = std::max(b.y1, s.p.y);
  }
  return b;
}

// The box, checked to lie within ±kMaxCoordinate: beyond, views and rasters overflow.
Box checked(const Box& b, const Ifs& ifs) {
  const double far = std::max({std::abs(b.x0), std::abs(b.y0), std::abs(b.x1), std::abs(b.y1)});
  if (!(far <= kMaxCoordinate))
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("{}: the attractor reaches {:.3g} from the origin, beyond ±{:g} (scale "
                            "the IFS down)",
                            ifs.name.empty() ? "IFS" : ifs.name, far, kMaxCoordinate));
  return b;
}

}  // namespace

Box attractor_bounds(const Ifs& ifs, std::uint64_t seed, const CancelToken& cancel) {
  detail::check_chaos_game({.ifs = ifs});
  const double s = ifs.contraction();
  if (!(s < 1)) return checked(bounds_by_sampling(ifs, seed, cancel), ifs);

  // A lies in the disc around any point c of radius max_n |f_n(c) − c| / (1 − s); take c the
  // fixed point of a map with an inverse of I − M (any point would do, a nearby one converges
  // sooner).
  Point c{0, 0};
  {
    const AffineMap& f = ifs.maps[0];
    const AffineMap i_minus_m{1 - f.a, -f.b, -f.c, 1 - f.d, 0, 0};
    if (auto inv = i_minus_m.inverse()) c = (*inv)(Point{f.e, f.f});
  }
  double radius = 0;
  for (const auto& f : ifs.maps) {
    const Point q = f(c);
    radius = std::max(radius, std::hypot(q.x - c.x, q.y - c.y));
  }
  radius /= (1 - s);

  // h_{k+1}(u) = max_n [u·t_n + h_k(M_nᵀ u)]: the support function of W(B) from that of B. It is
  // monotone and contracts by s, so from the disc it decreases to the support function of A.
  // h is sampled at K directions u_j; h at M_nᵀu_j is |M_nᵀu_j| times h linearly interpolated at
  // its direction. Those directions never change, so each (n, j) pair's interpolation cell,
  // weight, length and offset u_j·t_n are computed once.
  constexpr std::size_t kDirections = 2048;  // a multiple of 4: the axes are sampled exactly
  struct Term {
    std::uint32_t j0, j1;
    double w0, w1;  // interpolation weights, already scaled by |M_nᵀ u_j|
    double offset;  // u_j · t_n
  };
  const std::size_t maps = ifs.maps.size();
  std::vector<Term> terms(kDirections * maps);
  std::vector<double> h(kDirections), next(kDirections);
  for (std::size_t j = 0; j < kDirections; ++j) {
    const double theta = 2 * std::numbers::pi * static_cast<double>(j) / kDirections;
    const Point u{std::cos(theta), std::sin(theta)};
    h[j] = u.x * c.x + u.y * c.y + radius;
    for (std::size_t n = 0; n < maps; ++n) {
      const AffineMap& f = ifs.maps[n];
      const Point v{f.a * u.x + f.c * u.y, f.b * u.x + f.d * u.y};
      const double r = std::hypot(v.x, v.y);
      double t = std::atan2(v.y, v.x) / (2 * std::numbers::pi);
      if (t < 0) t += 1;
      const double pos = t * kDirections;
      const auto j0 = static_cast<std::uint32_t>(static_cast<std::size_t>(pos) % kDirections);
      const double w = pos - std::floor(pos);
      terms[j * maps + n] = {j0, static_cast<std::uint32_t>((j0 + 1) % kDirections), r * (1 - w),
                             r * w, u.x * f.e + u.y * f.f};
    }
  }
  const double tolerance = 1e-11 * std::max(radius, 1e-300);
  for (int iteration = 0; iteration < 5000; ++iteration) {
    if (iteration % 64 == 0) cancel.check("attractor bounds");
    double change = 0;
    for (std::size_t j = 0; j < kDirections; ++j) {
      double best = -INFINITY;
      for (std::size_t n = 0; n < maps; ++n) {
        const Term& t = terms[j * maps + n];
        best = std::max(best, t.offset + t.w0 * h[t.j0] + t.w1 * h[t.j1]);
      }
      next[j] = best;
      change = std::max(change, std::abs(best - h[j]));
    }
    std::swap(h, next);
    if (change < tolerance) break;
  }
  return checked({-h[kDirections / 2], -h[3 * kDirections / 4], h[0], h[kDirections / 4]}, ifs);
}

Box fit_view(const Box& bounds, cv::Size size, double margin) {
  if (!(margin >= 0 && margin <= kMaxMargin))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("margin: must be a number in [0, {:g}] (got {})", kMaxMargin, margin));
  double w = bounds.width(), h = bounds.height();
  const double largest = std::max(w, h);
  // A line or a point still shows; and the view is never narrower than its pixels can resolve in
  // double precision at its coordinates (kMinRelativeExtent of them), nor than 1e-100 (its pixel
  // scale stays finite).
  const double magnitude = std::max(
      {std::abs(bounds.x0), std::abs(bounds.y0), std::abs(bounds.x1), std::abs(bounds.y1)});
  const double minimum =
      std::max({largest > 0 ? largest * 1e-3 : 1.0, kMinRelativeExtent * magnitude, 1e-100});
  w = std::max(w, minimum);
  h = std::max(h, minimum);
  const double pad = margin * std::max(w, h);
  w += 2 * pad;
  h += 2 * pad;
  const double aspect = static_cast<double>(size.width) / size.height;
  if (w / h < aspect)
    w = h * aspect;
  else
    h = w / aspect;
  const double cx = 0.5 * (bounds.x0 + bounds.x1), cy = 0.5 * (bounds.y0 + bounds.y1);
  return {cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2};
}

namespace {

std::vector<double> parse_numbers(const std::string& text, char separator, const std::string& what,
                                  const char* form) {
  std::vector<double> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find(separator, start);
    std::string item = text.substr(start, end == std::string::npos ? end : end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    double value = 0;
    const auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || ptr != item.data() + item.size() ||
        !std::isfinite(value))
      throw Error(ErrorKind::parse, fmt::format("{}: expected {} (got '{}')", what, form, text));
    out.push_back(value);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

Box parse_box(const std::string& text, const std::string& what) {
  const auto v = parse_numbers(text, ',', what, "x0,y0,x1,y1");
  if (v.size() != 4)
    throw Error(ErrorKind::parse, fmt::format("{}: expected x0,y0,x1,y1 (got '{}')", what, text));
  if (!(v[2] > v[0]) || !(v[3] > v[1]))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: needs x1 > x0 and y1 > y0 (got '{}')", what, text));
  for (const double x : v)
    if (std::abs(x) > kMaxCoordinate)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: coordinates must lie within ±{:g} (got '{}')", what,
                              kMaxCoordinate, text));
  // Pixels narrower than the spacing of doubles at these coordinates would all be one point.
  const double magnitude =
      std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2]), std::abs(v[3])});
  if (std::min(v[2] - v[0], v[3] - v[1]) < std::max(kMinRelativeExtent * magnitude, 1e-100))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: too narrow for double precision at these coordinates: each side "
                            "must be at least {:g} times the largest coordinate and 1e-100 (got "
                            "'{}')",
                            what, kMinRelativeExtent, text));
  return {v[0], v[1], v[2], v[3]};
}

void check_size(cv::Size size, const std::string& what) {
  constexpr int kLargest = 32768;
  if (size.width < 1 || size.height < 1 || size.width > kLargest || size.height > kLargest)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: each side must be 1 to {} pixels (got {}x{})", what, kLargest,
                            size.width, size.height));
}

void check_view(const Box& v, const std::string& what) {
  if (!(v.x1 > v.x0) || !(v.y1 > v.y0) || !std::isfinite(v.x0) || !std::isfinite(v.x1) ||
      !std::isfinite(v.y0) || !std::isfinite(v.y1))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: must be a rectangle x0 < x1, y0 < y1 of finite numbers "
                            "(got {},{},{},{})",
                            what, v.x0, v.y0, v.x1, v.y1));
}

cv::Size parse_size(const std::string& text, const std::string& what) {
  std::string lowered = text;
  std::replace(lowered.begin(), lowered.end(), 'X', 'x');
  const auto v = parse_numbers(lowered, 'x', what, "WxH");
  if (v.size() != 2 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) ||
      std::abs(v[0]) > 1e9 || std::abs(v[1]) > 1e9)
    throw Error(ErrorKind::parse,
                fmt::format("{}: expected WxH in whole pixels (got '{}')", what, text));
  const cv::Size size{static_cast<int>(v[0]), static_cast<int>(v[1])};
  check_size(size, what);
  return size;
}

}  // namespace ifsfx
