// SPDX-License-Identifier: Apache-2.0
// The variations flam3 took from Apophysis' plugins after the paper's 49 (disc2 … mobius, less
// the complex functions of variations_complex.cpp), written from their published definitions
// (the plugins' documentation, as catalogued at jwfsanctuary.club "Variation information"). Each
// returns w·V(p); φ = atan2(y, x) unless a comment says θ.
#include <algorithm>
#include <cmath>

#include "flame/detail/variation_math.h"

namespace ifsfx::flame::detail {
namespace {

constexpr double kHalfPi = kPi / 2;

// disc2: disc with a rotation of its π·r term and a twist; a twist beyond ±2π also scales.
constexpr VariationParameter kDisc2[] = {{"disc2_rot", 0}, {"disc2_twist", 0}};
Point disc2(const VariationInput& in, Rng&) {
  const double rot = in.params[0], twist = in.params[1];
  double sin_add = std::sin(twist), cos_add = std::cos(twist) - 1;
  double k = 1;
  if (twist > 2 * kPi) k = 1 + twist - 2 * kPi;
  if (twist < -2 * kPi) k = 1 + twist + 2 * kPi;
  sin_add *= k;
  cos_add *= k;
  const double t = rot * kPi * (in.p.x + in.p.y);
  const double r = in.w * polar(in).theta() / kPi;
  return {(std::sin(t) + cos_add) * r, (std::cos(t) + sin_add) * r};
}

// Gielis' superformula radius at angle m/4·φ + π/4, blended with a random radius by rnd.
constexpr VariationParameter kSuperShape[] = {{"super_shape_rnd", 0}, {"super_shape_m", 0},
                                              {"super_shape_n1", 1},  {"super_shape_n2", 1},
                                              {"super_shape_n3", 1},  {"super_shape_holes", 0}};
Point super_shape(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double rnd = k[0], m = k[1], n1 = k[2], n2 = k[3], n3 = k[4], holes = k[5];
  const Polar q = polar(in);
  const double theta = m / 4 * q.phi() + kPi / 4;
  const double t1 = std::pow(std::abs(std::cos(theta)), n2);
  const double t2 = std::pow(std::abs(std::sin(theta)), n3);
  const double r = q.r();
  const double rr = (rnd * psi(rng) + (1 - rnd) * r - holes) * std::pow(t1 + t2, -1 / n1);
  return scaled(in.w * rr / (r + kEps), in.p.x, in.p.y);
}

constexpr VariationParameter kFlower[] = {{"flower_petals", 0}, {"flower_holes", 0}};
Point flower(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double r = in.w * (psi(rng) - in.params[1]) * std::cos(in.params[0] * q.phi());
  return scaled(r / (q.r() + kEps), in.p.x, in.p.y);
}

constexpr VariationParameter kConic[] = {{"conic_eccentricity", 1}, {"conic_holes", 0}};
Point conic(const VariationInput& in, Rng& rng) {
  const Polar q = polar(in);
  const double e = in.params[0], r = q.r() + kEps, ct = in.p.x / r;
  const double k = in.w * (psi(rng) - in.params[1]) * e / (1 + e * ct) / r;
  return scaled(k, in.p.x, in.p.y);
}

constexpr VariationParameter kParabola[] = {{"parabola_height", 0}, {"parabola_width", 0}};
Point parabola(const VariationInput& in, Rng& rng) {
  const double r = polar(in).r(), s = std::sin(r), c = std::cos(r);
  const double u = psi(rng), v = psi(rng);
  return scaled(in.w, in.params[0] * s * s * u, in.params[1] * c * v);
}

constexpr VariationParameter kBent2[] = {{"bent2_x", 1}, {"bent2_y", 1}};
Point bent2(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, x < 0 ? x * in.params[0] : x, y < 0 ? y * in.params[1] : y);
}

// Bipolar coordinates: (½·ln((t + 2x)/(t − 2x)) / 2, ½·atan2(2y, r² − 1) − shift·π/2), the
// angle folded into (−π/2, π/2], both scaled by 2/π.
constexpr VariationParameter kBipolar[] = {{"bipolar_shift", 0}};
Point bipolar(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double r2 = x * x + y * y, t = r2 + 1, x2 = 2 * x;
  double v = 0.5 * std::atan2(2 * y, r2 - 1) - kHalfPi * in.params[0];
  if (v > kHalfPi) {
    v = -kHalfPi + std::fmod(v + kHalfPi, kPi);
  } else if (v < -kHalfPi) {
    v = kHalfPi - std::fmod(kHalfPi - v, kPi);
  }
  const double u = 0.25 * std::log((t + x2) / (t - x2));
  return scaled(in.w * 2 / kPi, u, v);
}

// Each unit cell shrunk by half about its centre; a quarter of the points to a border strip.
Point boarders(const VariationInput& in, Rng& rng) {
  const auto [x, y] = in.p;
  const double rx = std::rint(x), ry = std::rint(y), ox = x - rx, oy = y - ry;
  const double hx = ox * 0.5 + rx, hy = oy * 0.5 + ry;
  if (psi(rng) >= 0.75) return scaled(in.w, hx, hy);
  if (std::abs(ox) >= std::abs(oy)) {
    const double s = ox >= 0 ? 0.25 : -0.25;
    return scaled(in.w, hx + s, hy + s * oy / ox);
  }
  const double s = oy >= 0 ? 0.25 : -0.25;
  return scaled(in.w, hx + s * ox / oy, hy + s);
}

Point butterfly(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double y2 = 2 * y;
  const double k = 4 / std::sqrt(3 * kPi) * std::sqrt(std::abs(x * y) / (x * x + y2 * y2 + kEps));
  return scaled(in.w * k, x, y2);
}

// Cells of side `size` re-laid on the quadrant's even/odd lattice, y flipped.
constexpr VariationParameter kCell[] = {{"cell_size", 1}};
Point cell(const VariationInput& in, Rng&) {
  const double size = in.params[0], inv = 1 / (size + kEps);
  double cx = std::floor(in.p.x * inv), cy = std::floor(in.p.y * inv);
  const double dx = in.p.x - cx * size, dy = in.p.y - cy * size;
  cx = cx >= 0 ? 2 * cx : -(2 * cx + 1);
  cy = cy >= 0 ? 2 * cy : -(2 * cy + 1);
  return scaled(in.w, dx + cx * size, -(dy + cy * size));
}

// z^(r + i·i)/power on one of `power` random branches.
constexpr VariationParameter kCpow[] = {{"cpow_r", 1}, {"cpow_i", 0}, {"cpow_power", 1}};
Point cpow(const VariationInput& in, Rng& rng) {
  const double cr = in.params[0], ci = in.params[1], pw = in.params[2];
  const Polar q = polar(in);
  const double a = q.phi(), lnr = 0.5 * std::log(q.r2());
  const double vc = cr / pw, vd = ci / pw;
  const double ang = vc * a + vd * lnr + 2 * kPi / pw * std::floor(pw * psi(rng));
  const double m = in.w * std::exp(vc * lnr - vd * a);
  return {m * std::cos(ang), m * std::sin(ang)};
}

constexpr VariationParameter kCurve[] = {
    {"curve_xamp", 0}, {"curve_yamp", 0}, {"curve_xlength", 1}, {"curve_ylength", 1}};
Point curve(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double xl = std::max(in.params[2] * in.params[2], 1e-20);
  const double yl = std::max(in.params[3] * in.params[3], 1e-20);
  return scaled(in.w, x + in.params[0] * std::exp(-y * y / xl),
                y + in.params[1] * std::exp(-x * x / yl));
}

// Elliptic coordinates of the point, mapped back on the unit disc.
Point edisc(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double t = x * x + y * y + 1, x2 = 2 * x;
  const double xmax = (std::sqrt(t + x2) + std::sqrt(t - x2)) / 2;
  const double a1 = std::log(xmax + std::sqrt(std::max(xmax - 1, 0.0)));
  const double a2 = -std::acos(std::clamp(x / xmax, -1.0, 1.0));
  const double w = in.w / 11.57034632;
  const double snv = y > 0 ? -std::sin(a1) : std::sin(a1);
  return {w * std::cosh(a2) * std::cos(a1), w * std::sinh(a2) * snv};
}

Point elliptic(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double t = x * x + y * y + 1, x2 = 2 * x;
  const double xmax = 0.5 * (std::sqrt(t + x2) + std::sqrt(t - x2));
  const double a = x / xmax, b = std::sqrt(std::max(1 - a * a, 0.0));
  const double ssx = std::sqrt(std::max(xmax - 1, 0.0));
  const double w = in.w / kHalfPi;
  const double v = std::log(xmax + ssx);
  return {w * std::atan2(a, b), y > 0 ? w * v : -w * v};
}

// The Escher twist: z^((1 + e^(iβ))/2).
constexpr VariationParameter kEscher[] = {{"escher_beta", 0}};
Point escher(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double a = q.phi(), lnr = 0.5 * std::log(q.r2());
  const double vc = 0.5 * (1 + std::cos(in.params[0])), vd = 0.5 * std::sin(in.params[0]);
  const double m = in.w * std::exp(vc * lnr - vd * a), n = vc * a + vd * lnr;
  return {m * std::cos(n), m * std::sin(n)};
}

Point foci(const VariationInput& in, Rng&) {
  const double ex = 0.5 * std::exp(in.p.x), enx = 0.25 / ex;
  const double k = in.w / (ex + enx - std::cos(in.p.y));
  return {k * (ex - enx), k * std::sin(in.p.y)};
}

// Inside the disc of radius w about (x0, −y0) the plane spins (and twists), outside it is pushed
// out by `space`.
constexpr VariationParameter kLazysusan[] = {{"lazysusan_spin", 0},
                                             {"lazysusan_space", 0},
                                             {"lazysusan_twist", 0},
                                             {"lazysusan_x", 0},
                                             {"lazysusan_y", 0}};
Point lazysusan(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const double spin = k[0], space = k[1], twist = k[2], cx = k[3], cy = k[4];
  const double xx = in.p.x - cx, yy = in.p.y + cy, rr = std::sqrt(xx * xx + yy * yy);
  if (rr < in.w) {
    const double a = std::atan2(yy, xx) + spin + twist * (in.w - rr);
    return {in.w * rr * std::cos(a) + cx, in.w * rr * std::sin(a) - cy};
  }
  const double s = in.w * (1 + space / (rr + kEps));
  return {s * xx + cx, s * yy - cy};
}

// Inside the circle of radius w: reflected radially as √(w²/r² − 1); outside: linear.
Point loonie(const VariationInput& in, Rng&) {
  const double r2 = polar(in).r2(), w2 = in.w * in.w;
  if (r2 < w2 && r2 != 0) return scaled(in.w * std::sqrt(w2 / r2 - 1), in.p.x, in.p.y);
  return scaled(in.w, in.p.x, in.p.y);
}

// A Gaussian offset of size w added to the affine point before the other variations.
Point pre_blur(const VariationInput& in, Rng& rng) {
  const double g = in.w * sum_of_four(rng), a = 2 * kPi * psi(rng);
  return {g * std::cos(a), g * std::sin(a)};
}

constexpr VariationParameter kModulus[] = {{"modulus_x", 1}, {"modulus_y", 1}};
double wrap_into(double v, double m) {
  if (v > m) return -m + std::fmod(v + m, 2 * m);
  if (v < -m) return m - std::fmod(m - v, 2 * m);
  return v;
}
Point modulus(const VariationInput& in, Rng&) {
  return scaled(in.w, wrap_into(in.p.x, in.params[0]), wrap_into(in.p.y, in.params[1]));
}

// Points under a (damped) cosine trace of x are mirrored in y.
constexpr VariationParameter kOscilloscope[] = {{"oscilloscope_separation", 1},
                                                {"oscilloscope_frequency", kPi},
                                                {"oscilloscope_amplitude", 1},
                                                {"oscilloscope_damping", 0}};
Point oscilloscope(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const double sep = k[0], freq = k[1], amp = k[2], damp = k[3];
  const double wave = amp * std::cos(2 * kPi * freq * in.p.x);
  const double t = (damp == 0 ? wave : std::exp(-std::abs(in.p.x) * damp) * wave) + sep;
  return scaled(in.w, in.p.x, std::abs(in.p.y) <= t ? -in.p.y : in.p.y);
}

// (θ/π, ln(r²)/(2π)), θ = atan2(x, y) as the paper's polar.
Point polar2(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double k = in.w / kPi;
  return {k * q.theta(), k / 2 * std::log(q.r2())};
}

constexpr VariationParameter kPopcorn2[] = {
    {"popcorn2_x", 0}, {"popcorn2_y", 0}, {"popcorn2_c", 0}};
Point popcorn2(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const auto& k = in.params;
  return scaled(in.w, x + k[0] * std::sin(std::tan(y * k[2])),
                y + k[1] * std::sin(std::tan(x * k[2])));
}

// The weight enters inside: 1/(r·(r² + 1/w)), not w times it.
Point scry(const VariationInput& in, Rng&) {
  const double t = polar(in).r2();
  const double k = 1 / (std::sqrt(t) * (t + 1 / (in.w + kEps)) + kEps);
  return scaled(k, in.p.x, in.p.y);
}

constexpr VariationParameter kSeparation[] = {
    {"separation_x", 0}, {"separation_xinside", 0}, {"separation_y", 0}, {"separation_yinside", 0}};
double separate(double v, double s, double inside) {
  const double h = std::sqrt(v * v + s * s);
  return v > 0 ? h - v * inside : -(h + v * inside);
}
Point separation(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  return scaled(in.w, separate(in.p.x, k[0], k[1]), separate(in.p.y, k[2], k[3]));
}

// The sign of y follows cos(π·xsize·x); the sign of x follows cos(π·ysize·y).
constexpr VariationParameter kSplit[] = {{"split_xsize", 0}, {"split_ysize", 0}};
Point split(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double ny = std::cos(x * in.params[0] * kPi) >= 0 ? y : -y;
  const double nx = std::cos(y * in.params[1] * kPi) >= 0 ? x : -x;
  return scaled(in.w, nx, ny);
}

constexpr VariationParameter kSplits[] = {{"splits_x", 0}, {"splits_y", 0}};
Point splits(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  return scaled(in.w, x >= 0 ? x + in.params[0] : x - in.params[0],
                y >= 0 ? y + in.params[1] : y - in.params[1]);
}

constexpr VariationParameter kStripes[] = {{"stripes_space", 0}, {"stripes_warp", 0}};
Point stripes(const VariationInput& in, Rng&) {
  const double rx = std::floor(in.p.x + 0.5), ox = in.p.x - rx;
  return scaled(in.w, ox * (1 - in.params[0]) + rx, in.p.y + ox * ox * in.params[1]);
}

// The plane cut into `count` wedges, each closed up by `angle`; swirl turns with r.
double wedge_angle(double a, double angle, double count) {
  const double c = std::floor((count * a + kPi) / (2 * kPi));
  return a * (1 - angle * count / (2 * kPi)) + c * angle;
}

constexpr VariationParameter kWedge[] = {
    {"wedge_angle", 0}, {"wedge_hole", 0}, {"wedge_count", 1}, {"wedge_swirl", 0}};
Point wedge(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const Polar q = polar(in);
  const double r = q.r();
  const double a = wedge_angle(q.phi() + k[3] * r, k[0], k[2]);
  return scaled(in.w * (r + k[1]), std::cos(a), std::sin(a));
}

constexpr VariationParameter kWedgeJulia[] = {{"wedge_julia_angle", 0},
                                              {"wedge_julia_count", 1},
                                              {"wedge_julia_power", 1},
                                              {"wedge_julia_dist", 0}};
Point wedge_julia(const VariationInput& in, Rng& rng) {
  const auto& k = in.params;
  const double angle = k[0], count = k[1], pw = k[2], dist = k[3];
  const Polar q = polar(in);
  const double r = in.w * std::pow(q.r2(), dist / pw / 2);
  const double branch = std::trunc(std::abs(pw) * psi(rng));
  const double a = wedge_angle((q.phi() + 2 * kPi * branch) / pw, angle, count);
  return {r * std::cos(a), r * std::sin(a)};
}

constexpr VariationParameter kWedgeSph[] = {
    {"wedge_sph_angle", 0}, {"wedge_sph_count", 1}, {"wedge_sph_hole", 0}, {"wedge_sph_swirl", 0}};
Point wedge_sph(const VariationInput& in, Rng&) {
  const auto& k = in.params;
  const Polar q = polar(in);
  const double r = 1 / (q.r() + kEps);
  const double a = wedge_angle(q.phi() + k[3] * r, k[0], k[1]);
  return scaled(in.w * (r + k[2]), std::cos(a), std::sin(a));
}

// Inside the circle of radius w the angle turns by inside/(w − r), outside by outside/(w − r).
constexpr VariationParameter kWhorl[] = {{"whorl_inside", 0}, {"whorl_outside", 0}};
Point whorl(const VariationInput& in, Rng&) {
  const Polar q = polar(in);
  const double r = q.r();
  const double turn = (r < in.w ? in.params[0] : in.params[1]) / (in.w - r);
  const double a = q.phi() + turn;
  return scaled(in.w * r, std::cos(a), std::sin(a));
}

constexpr VariationParameter kWaves2[] = {
    {"waves2_scalex", 0}, {"waves2_scaley", 0}, {"waves2_freqx", 0},
    {"waves2_freqy", 0},  {"waves2_scalez", 0}, {"waves2_freqz", 0}};  // z: Ember's, no-ops
Point waves2(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const auto& k = in.params;
  return scaled(in.w, x + k[0] * std::sin(y * k[2]), y + k[1] * std::sin(x * k[3]));
}

constexpr VariationParameter kAuger[] = {
    {"auger_freq", 1},
    {"auger_weight", 0.5},
    {"auger_sym", 0},
    {"auger_scale", 1},
    {"auger_half_scale", 0.5}};  // Ember writes scale/2 out too; unused
Point auger(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double freq = in.params[0], aw = in.params[1], sym = in.params[2], sc = in.params[3];
  const double s = std::sin(freq * x), t = std::sin(freq * y);
  const double dy = y + aw * (sc * s / 2 + std::abs(y) * s);
  const double dx = x + aw * (sc * t / 2 + std::abs(x) * t);
  return scaled(in.w, x + sym * (dx - x), dy);
}

// The mean of the bipolar radii and angles about (±w, 0).
constexpr VariationParameter kFlux[] = {{"flux_spread", 0}};
Point flux(const VariationInput& in, Rng&) {
  const auto [x, y] = in.p;
  const double xpw = x + in.w, xmw = x - in.w;
  const double ratio = std::sqrt(y * y + xpw * xpw) / (std::sqrt(y * y + xmw * xmw) + kEps);
  const double r = in.w * (2 + in.params[0]) * std::sqrt(ratio);
  const double a = (std::atan2(y, xmw) - std::atan2(y, xpw)) * 0.5;
  return {r * std::cos(a), r * std::sin(a)};
}

// The Möbius map (a·z + b)/(c·z + d) of complex a, b, c, d.
constexpr VariationParameter kMobius[] = {
    {"mobius_re_a", 1}, {"mobius_im_a", 0}, {"mobius_re_b", 0}, {"mobius_im_b", 0},
    {"mobius_re_c", 0}, {"mobius_im_c", 0}, {"mobius_re_d", 1}, {"mobius_im_d", 0}};
Point mobius(const VariationInput& in, Rng&) {
  return mobius_map(in);
}

}  // namespace

void add_flam3_variations(std::vector<Variation>& out) {
  using K = VariationKind;
  const Variation rows[] = {
      {.name = "disc2", .parameters = kDisc2, .function = disc2},
      {.name = "super_shape",
       .parameters = kSuperShape,
       .function = super_shape,
       .kind = K::random},
      {.name = "flower", .parameters = kFlower, .function = flower, .kind = K::random},
      {.name = "conic", .parameters = kConic, .function = conic, .kind = K::random},
      {.name = "parabola", .parameters = kParabola, .function = parabola, .kind = K::random},
      {.name = "bent2", .parameters = kBent2, .function = bent2},
      {.name = "bipolar", .parameters = kBipolar, .function = bipolar},
      {.name = "boarders", .function = boarders, .kind = K::random},
      {.name = "butterfly", .function = butterfly},
      {.name = "cell", .parameters = kCell, .function = cell},
      {.name = "cpow", .parameters = kCpow, .function = cpow, .kind = K::random},
      {.name = "curve", .parameters = kCurve, .function = curve},
      {.name = "edisc", .function = edisc},
      {.name = "elliptic", .function = elliptic},
      {.name = "escher", .parameters = kEscher, .function = escher},
      {.name = "foci", .function = foci},
      {.name = "lazysusan", .parameters = kLazysusan, .function = lazysusan},
      {.name = "loonie", .function = loonie},
      {.name = "pre_blur",
       .function = pre_blur,
       .kind = K::random,
       .place = VariationPlace::pre_only,
       .assign = Assign::add},
      {.name = "modulus", .parameters = kModulus, .function = modulus},
      {.name = "oscilloscope", .parameters = kOscilloscope, .function = oscilloscope},
      {.name = "polar2", .function = polar2},
      {.name = "popcorn2", .parameters = kPopcorn2, .function = popcorn2},
      {.name = "scry", .function = scry},
      {.name = "separation", .parameters = kSeparation, .function = separation},
      {.name = "split", .parameters = kSplit, .function = split},
      {.name = "splits", .parameters = kSplits, .function = splits},
      {.name = "stripes", .parameters = kStripes, .function = stripes},
      {.name = "wedge", .parameters = kWedge, .function = wedge},
      {.name = "wedge_julia",
       .parameters = kWedgeJulia,
       .function = wedge_julia,
       .kind = K::random},
      {.name = "wedge_sph", .parameters = kWedgeSph, .function = wedge_sph},
      {.name = "whorl", .parameters = kWhorl, .function = whorl},
      {.name = "waves2", .parameters = kWaves2, .function = waves2},
      {.name = "auger", .parameters = kAuger, .function = auger},
      {.name = "flux", .parameters = kFlux, .function = flux},
      {.name = "mobius", .parameters = kMobius, .function = mobius},
  };
  out.insert(out.end(), std::begin(rows), std::end(rows));
}

}  // namespace ifsfx::flame::detail
