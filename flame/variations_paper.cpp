// SPDX-License-Identifier: Apache-2.0
// Variations 0–48 of the paper's catalogue (Draves & Reckase, "The Fractal Flame Algorithm",
// appendix), written from its formulas. Each returns w·V(p). Where the paper's text has a known
// slip (fan2's, ngon's and the rings' floor terms), the comment says what is used instead.
// The "dependent" ones read the xform's affine map; the paper names its coefficients
// x' = a·x + b·y + c, y' = d·x + e·y + f, which are AffineMap's a, b, e, c, d, f.
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

Point linear(const VariationInput& in, Rng&) {
  return scaled(in.w, in.p.x, in.p.y);
}

Point sinusoidal(const VariationInput& in, Rng&) {
  return scaled(in.w, std::sin(in.p.x), std::sin(in.p.y));
}

Point spherical(const VariationInput& in, Rng&) {
  const double k = 1.0 / (polar(in).r2() + kEps);
  return scaled(in.w * k, in.p.x, in.p.y);
}

Point swirl(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double r2 = x * x + y * y, s = std::sin(r2), c = std::cos(r2);
  return scaled(in.w, x * s - y * c, x * c + y * s);
}

Point horseshoe(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double k = 1.0 / (polar(in).r() + kEps);
  return scaled(in.w * k, (x - y) * (x + y), 2 * x * y);
}

Point polar_v(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  return scaled(in.w, q.theta() / kPi, q.r() - 1);
}

Point handkerchief(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r(), t = q.theta();
  return scaled(in.w * r, std::sin(t + r), std::cos(t - r));
}

Point heart(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r(), t = q.theta();
  return scaled(in.w * r, std::sin(t * r), -std::cos(t * r));
}

Point disc(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double pr = kPi * q.r();
  return scaled(in.w * q.theta() / kPi, std::sin(pr), std::cos(pr));
}

Point spiral(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r() + kEps;
  return scaled(in.w / r, q.cos_theta() + std::sin(r), q.sin_theta() - std::cos(r));
}

Point hyperbolic(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r() + kEps;
  return scaled(in.w, q.sin_theta() / r, r * q.cos_theta());
}

Point diamond(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r();
  return scaled(in.w, q.sin_theta() * std::cos(r), q.cos_theta() * std::sin(r));
}

Point ex(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r(), t = q.theta();
  const double p0 = std::sin(t + r), p1 = std::cos(t - r);
  const double p03 = p0 * p0 * p0, p13 = p1 * p1 * p1;
  return scaled(in.w * r, p03 + p13, p03 - p13);
}

Point julia(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double a = q.theta() / 2 + omega(rng);
  return scaled(in.w * std::sqrt(q.r()), std::cos(a), std::sin(a));
}

Point bent(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, x < 0 ? 2 * x : x, y < 0 ? y / 2 : y);
}

// (x + b·sin(y / c²), y + e·sin(x / f²)), the paper's b, c, e, f.
Point waves(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const AffineMap& m = *in.pre;
  return scaled(in.w, x + m.b * std::sin(y / (m.e * m.e + kEps)),
                y + m.d * std::sin(x / (m.f * m.f + kEps)));
}

Point fisheye(const VariationInput& in, Rng&) {
  const double k = 2.0 / (polar(in).r() + 1);
  return scaled(in.w * k, in.p.y, in.p.x);  // the paper's swapped (y, x): eyefish is unswapped
}

// (x + c·sin(tan 3y), y + f·sin(tan 3x)), the paper's c, f: the translations.
Point popcorn(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const AffineMap& m = *in.pre;
  return scaled(in.w, x + m.e * std::sin(std::tan(3 * y)), y + m.f * std::sin(std::tan(3 * x)));
}

Point exponential(const VariationInput& in, Rng&) {
  const double k = std::exp(in.p.x - 1), a = kPi * in.p.y;
  return scaled(in.w * k, std::cos(a), std::sin(a));
}

Point power(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double s = q.sin_theta();
  return scaled(in.w * std::pow(q.r(), s), q.cos_theta(), s);
}

Point cosine(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, std::cos(kPi * x) * std::cosh(y), -std::sin(kPi * x) * std::sinh(y));
}

// ((r + c²) mod 2c² − c² + r(1 − c²))·(cos θ, sin θ), c the x translation. "mod" is fmod, the
// remainder with the dividend's sign, as the flame programs compute it.
Point rings(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double c2 = in.pre->e * in.pre->e + kEps, r = q.r();
  const double k = std::fmod(r + c2, 2 * c2) - c2 + r * (1 - c2);
  return scaled(in.w * k, q.cos_theta(), q.sin_theta());
}

// t = π c²; θ moves by ∓t/2 by which half of its period of length t (offset f) it lies in.
Point fan(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double t = kPi * (in.pre->e * in.pre->e + kEps), theta = q.theta();
  const double a = std::fmod(theta + in.pre->f, t) > t / 2 ? theta - t / 2 : theta + t / 2;
  return scaled(in.w * q.r(), std::cos(a), std::sin(a));
}

constexpr VariationParameter kBlob[] = {{"blob_high", 1}, {"blob_low", 0}, {"blob_waves", 1}};
Point blob(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double high = in.params[0], low = in.params[1], waves_n = in.params[2];
  const double r = q.r() * (low + (high - low) / 2 * (std::sin(waves_n * q.theta()) + 1));
  return scaled(in.w * r, q.sin_theta(), q.cos_theta());
}

constexpr VariationParameter kPdj[] = {{"pdj_a", 0}, {"pdj_b", 0}, {"pdj_c", 0}, {"pdj_d", 0}};
Point pdj(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const auto& k = in.params;
  return scaled(in.w, std::sin(k[0] * y) - std::cos(k[1] * x),
                std::sin(k[2] * x) - std::cos(k[3] * y));
}

// The paper prints t = θ + p2 − p1·trunc(2θp2/p1); the programs (and the picture's period of
// p1 in θ + p2) use trunc((θ + p2)/p1).
constexpr VariationParameter kFan2[] = {{"fan2_x", 0}, {"fan2_y", 0}};
Point fan2(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double p1 = kPi * (in.params[0] * in.params[0] + kEps), p2 = in.params[1];
  const double theta = q.theta();
  const double t = theta + p2 - p1 * std::trunc((theta + p2) / p1);
  const double a = t > p1 / 2 ? theta - p1 / 2 : theta + p1 / 2;
  return scaled(in.w * q.r(), std::sin(a), std::cos(a));
}

constexpr VariationParameter kRings2[] = {{"rings2_val", 0}};
Point rings2(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double p = in.params[0] * in.params[0] + kEps, r = q.r();
  const double t = r - 2 * p * std::trunc((r + p) / (2 * p)) + r * (1 - p);
  return scaled(in.w * t, q.sin_theta(), q.cos_theta());
}

Point eyefish(const VariationInput& in, Rng&) {
  const double k = 2.0 / (polar(in).r() + 1);
  return scaled(in.w * k, in.p.x, in.p.y);
}

Point bubble(const VariationInput& in, Rng&) {
  const double k = 4.0 / (polar(in).r2() + 4);
  return scaled(in.w * k, in.p.x, in.p.y);
}

Point cylinder(const VariationInput& in, Rng&) {
  return scaled(in.w, std::sin(in.p.x), in.p.y);
}

// The angle parameter is in quarter turns: p1 = angle·π/2.
constexpr VariationParameter kPerspective[] = {{"perspective_angle", 0}, {"perspective_dist", 0}};
Point perspective(const VariationInput& in, Rng&) {
  const double a = in.params[0] * kPi / 2, d = in.params[1];
  const double k = d / (d - in.p.y * std::sin(a) + kEps);
  return scaled(in.w * k, in.p.x, in.p.y * std::cos(a));
}

Point noise(const VariationInput& in, Rng& rng) {
  const double p1 = psi(rng), a = 2 * kPi * psi(rng);
  return scaled(in.w * p1, in.p.x * std::cos(a), in.p.y * std::sin(a));
}

constexpr VariationParameter kJulian[] = {{"julian_power", 1}, {"julian_dist", 1}};
Point julian(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double p = in.params[0], d = in.params[1];
  const double p3 = std::trunc(std::abs(p) * psi(rng));
  const double t = (q.phi() + 2 * kPi * p3) / p;
  return scaled(in.w * std::pow(q.r2(), d / p / 2), std::cos(t), std::sin(t));
}

constexpr VariationParameter kJuliascope[] = {{"juliascope_power", 1}, {"juliascope_dist", 1}};
Point juliascope(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double p = in.params[0], d = in.params[1];
  const double p3 = std::trunc(std::abs(p) * psi(rng));
  // The sign of φ alternates with the branch (the programs' rule; the paper draws Λ at random).
  const double sign = std::fmod(p3, 2.0) == 0 ? 1.0 : -1.0;
  const double t = (sign * q.phi() + 2 * kPi * p3) / p;
  return scaled(in.w * std::pow(q.r2(), d / p / 2), std::cos(t), std::sin(t));
}

Point blur(const VariationInput& in, Rng& rng) {
  const double p1 = psi(rng), a = 2 * kPi * psi(rng);
  return scaled(in.w * p1, std::cos(a), std::sin(a));
}

Point gaussian_blur(const VariationInput& in, Rng& rng) {
  const double g = sum_of_four(rng), a = 2 * kPi * psi(rng);
  return scaled(in.w * g, std::cos(a), std::sin(a));
}

// The term itself is w·(1/w)(…): the 1/w cancels, so w = 0 is fine.
constexpr VariationParameter kRadialBlur[] = {{"radial_blur_angle", 0}};
Point radial_blur(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double p1 = in.params[0] * kPi / 2;
  const double t1 = in.w * sum_of_four(rng), t2 = q.phi() + t1 * std::sin(p1);
  const double t3 = t1 * std::cos(p1) - 1, r = q.r();
  return {r * std::cos(t2) + t3 * in.p.x, r * std::sin(t2) + t3 * in.p.y};
}

constexpr VariationParameter kPie[] = {
    {"pie_slices", 6}, {"pie_rotation", 0}, {"pie_thickness", 0.5}};
Point pie(const VariationInput& in, Rng& rng) {
  const double slices = in.params[0], rotation = in.params[1], thickness = in.params[2];
  const double t1 = std::trunc(psi(rng) * slices + 0.5);
  const double t2 = rotation + 2 * kPi / slices * (t1 + psi(rng) * thickness);
  return scaled(in.w * psi(rng), std::cos(t2), std::sin(t2));
}

// The paper takes t3 − p2 when t3 ≤ p2/2; the angle to the nearer corner is t3 − p2 when
// t3 > p2/2, which is what the programs draw.
constexpr VariationParameter kNgon[] = {
    {"ngon_sides", 5}, {"ngon_power", 3}, {"ngon_circle", 1}, {"ngon_corners", 2}};
Point ngon(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double sides = in.params[0], pw = in.params[1], circle = in.params[2];
  const double corners = in.params[3];
  const double p2 = 2 * kPi / sides, phi = q.phi();
  double t3 = phi - p2 * std::floor(phi / p2);
  if (t3 > p2 / 2) t3 -= p2;
  const double k =
      (corners * (1 / (std::cos(t3) + kEps) - 1) + circle) / (std::pow(q.r2(), pw / 2) + kEps);
  return scaled(in.w * k, in.p.x, in.p.y);
}

constexpr VariationParameter kCurl[] = {{"curl_c1", 1}, {"curl_c2", 0}};
Point curl(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double c1 = in.params[0], c2 = in.params[1];
  const double t1 = 1 + c1 * x + c2 * (x * x - y * y), t2 = c1 * y + 2 * c2 * x * y;
  const double k = 1 / (t1 * t1 + t2 * t2 + kEps);
  return scaled(in.w * k, x * t1 + y * t2, y * t1 - x * t2);
}

// A zero size leaves its coordinate as it is.
constexpr VariationParameter kRectangles[] = {{"rectangles_x", 1}, {"rectangles_y", 1}};
Point rectangles(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double px = in.params[0], py = in.params[1];
  const double nx = px == 0 ? x : (2 * std::floor(x / px) + 1) * px - x;
  const double ny = py == 0 ? y : (2 * std::floor(y / py) + 1) * py - y;
  return scaled(in.w, nx, ny);
}

Point arch(const VariationInput& in, Rng& rng) {
  const double a = psi(rng) * kPi * in.w, s = std::sin(a);
  return scaled(in.w, s, s * s / std::cos(a));
}

Point tangent(const VariationInput& in, Rng&) {
  return scaled(in.w, std::sin(in.p.x) / std::cos(in.p.y), std::tan(in.p.y));
}

Point square(const VariationInput& in, Rng& rng) {
  const double u = psi(rng), v = psi(rng);
  return scaled(in.w, u - 0.5, v - 0.5);
}

Point rays(const VariationInput& in, Rng& rng) {
  const double k = in.w * std::tan(psi(rng) * kPi * in.w) / (polar(in).r2() + kEps);
  return scaled(in.w * k, std::cos(in.p.x), std::sin(in.p.y));
}

Point blade(const VariationInput& in, Rng& rng) {
  const double a = psi(rng) * polar(in).r() * in.w, c = std::cos(a), s = std::sin(a);
  return scaled(in.w * in.p.x, c + s, c - s);
}

// Apophysis's secant2 (flam3's name for the paper's secant): 1/cos(w·r), moved by ∓1 towards 0.
Point secant2(const VariationInput& in, Rng&) {
  const double c = std::cos(in.w * polar(in).r()), ic = 1 / c;
  return scaled(in.w, in.p.x, c < 0 ? ic + 1 : ic - 1);
}

Point twintrian(const VariationInput& in, Rng& rng) {
  const double a = psi(rng) * polar(in).r() * in.w, s = std::sin(a);
  double t = std::log10(s * s) + std::cos(a);
  if (!std::isfinite(t)) t = -30;  // sin a = 0: log10 0; the programs clamp it
  return scaled(in.w * in.p.x, t, t - kPi * s);
}

Point cross(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double d = x * x - y * y;
  const double k = std::sqrt(1 / (d * d + kEps));
  return scaled(in.w * k, x, y);
}

}  // namespace

void add_paper_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "linear", .function = linear},
      {.name = "sinusoidal", .function = sinusoidal},
      {.name = "spherical", .function = spherical},
      {.name = "swirl", .function = swirl},
      {.name = "horseshoe", .function = horseshoe},
      {.name = "polar", .function = polar_v},
      {.name = "handkerchief", .function = handkerchief},
      {.name = "heart", .function = heart},
      {.name = "disc", .function = disc},
      {.name = "spiral", .function = spiral},
      {.name = "hyperbolic", .function = hyperbolic},
      {.name = "diamond", .function = diamond},
      {.name = "ex", .function = ex},
      {.name = "julia", .function = julia, .kind = K::random},
      {.name = "bent", .function = bent},
      {.name = "waves", .function = waves, .kind = K::dependent},
      {.name = "fisheye", .function = fisheye},
      {.name = "popcorn", .function = popcorn, .kind = K::dependent},
      {.name = "exponential", .function = exponential},
      {.name = "power", .function = power},
      {.name = "cosine", .function = cosine},
      {.name = "rings", .function = rings, .kind = K::dependent},
      {.name = "fan", .function = fan, .kind = K::dependent},
      {.name = "blob", .parameters = kBlob, .function = blob},
      {.name = "pdj", .parameters = kPdj, .function = pdj},
      {.name = "fan2", .parameters = kFan2, .function = fan2},
      {.name = "rings2", .parameters = kRings2, .function = rings2},
      {.name = "eyefish", .function = eyefish},
      {.name = "bubble", .function = bubble},
      {.name = "cylinder", .function = cylinder},
      {.name = "perspective", .parameters = kPerspective, .function = perspective},
      {.name = "noise", .function = noise, .kind = K::random},
      {.name = "julian", .parameters = kJulian, .function = julian, .kind = K::random},
      {.name = "juliascope", .parameters = kJuliascope, .function = juliascope, .kind = K::random},
      {.name = "blur", .function = blur, .kind = K::random, .assign = Assign::add},
      {.name = "gaussian_blur",
       .function = gaussian_blur,
       .kind = K::random,
       .assign = Assign::add},
      {.name = "radial_blur",
       .parameters = kRadialBlur,
       .function = radial_blur,
       .kind = K::random},
      {.name = "pie",
       .parameters = kPie,
       .function = pie,
       .kind = K::random,
       .assign = Assign::add},
      {.name = "ngon", .parameters = kNgon, .function = ngon},
      {.name = "curl", .parameters = kCurl, .function = curl},
      {.name = "rectangles", .parameters = kRectangles, .function = rectangles},
      {.name = "arch", .function = arch, .kind = K::random, .assign = Assign::add},
      {.name = "tangent", .function = tangent},
      {.name = "square", .function = square, .kind = K::random, .assign = Assign::add},
      {.name = "rays", .function = rays, .kind = K::random},
      {.name = "blade", .function = blade, .kind = K::random},
      {.name = "secant2", .function = secant2},
      {.name = "twintrian", .function = twintrian, .kind = K::random},
      {.name = "cross", .function = cross},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
