// SPDX-License-Identifier: Apache-2.0
// The paper's variations (Draves & Reckase, appendix) at points where their formulas are worked
// by hand: r = √(x² + y²), θ = atan2(x, y) (measured from the y axis), φ = atan2(y, x).
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "flame/detail/batch_variations.h"
#include "ifs/cpu.h"
#include "variation_check.h"

namespace ifsfx::flame {
namespace {

using test::eval;
constexpr double kPi = std::numbers::pi;

TEST(variations, registry_names_are_unique_and_ids_are_positions) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < variations().size(); ++i) {
    const Variation& v = variations()[i];
    EXPECT_EQ(v.id, i);
    EXPECT_TRUE(names.insert(v.name).second) << v.name;
    EXPECT_EQ(find_variation(v.name), &v);
    EXPECT_NE(v.function, nullptr) << v.name;
  }
  EXPECT_EQ(find_variation("no_such_variation"), nullptr);
}

TEST(variations, docs_flames_md_lists_every_variation_of_the_registry) {
  std::ifstream in(std::string(IFSFX_SOURCE_DIR) + "/docs/flames.md");
  std::stringstream text;
  text << in.rdbuf();
  for (const Variation& v : variations())
    EXPECT_NE(text.str().find("| `" + std::string(v.name) + "` |"), std::string::npos) << v.name;
}

TEST(variations, linear_scales_by_the_weight) {
  EXPECT_POINT_NEAR(eval("linear", {2, -3}, 0.5), 1, -1.5);
}

TEST(variations, sinusoidal_spherical_swirl_horseshoe) {
  EXPECT_POINT_NEAR(eval("sinusoidal", {kPi / 2, kPi / 6}), 1, 0.5);
  EXPECT_POINT_NEAR(eval("spherical", {1, 1}), 0.5, 0.5);  // (x, y) / r²
  EXPECT_POINT_NEAR(eval("spherical", {2, 0}, 2), 1, 0);
  // r² = 1: (x sin 1 − y cos 1, x cos 1 + y sin 1) at (1, 0)
  EXPECT_POINT_NEAR(eval("swirl", {1, 0}), std::sin(1.0), std::cos(1.0));
  // r = 5: ((x − y)(x + y), 2xy) / r
  EXPECT_POINT_NEAR(eval("horseshoe", {3, 4}), -1.4, 4.8);
}

TEST(variations, polar_measures_theta_from_the_y_axis) {
  EXPECT_POINT_NEAR(eval("polar", {1, 0}), 0.5, 0);  // θ = π/2, r − 1 = 0
  EXPECT_POINT_NEAR(eval("polar", {0, 2}), 0, 1);    // θ = 0
}

TEST(variations, handkerchief_heart_disc_spiral) {
  // (0, 1): r = 1, θ = 0
  EXPECT_POINT_NEAR(eval("handkerchief", {0, 1}), std::sin(1.0), std::cos(-1.0));
  EXPECT_POINT_NEAR(eval("heart", {1, 0}), 1, 0);    // θ = π/2: (sin π/2, −cos π/2)
  EXPECT_POINT_NEAR(eval("disc", {1, 0}), 0, -0.5);  // θ/π = 1/2: (sin π, cos π)/2
  EXPECT_POINT_NEAR(eval("spiral", {0, 1}), 1 + std::sin(1.0), -std::cos(1.0));
}

TEST(variations, hyperbolic_diamond_ex) {
  // (3, 4): r = 5, sin θ = 3/5, cos θ = 4/5
  EXPECT_POINT_NEAR(eval("hyperbolic", {3, 4}), 0.12, 4);
  EXPECT_POINT_NEAR(eval("diamond", {3, 4}), 0.17019731127793575, -0.7671394197305108);
  // (0, 1): p0 = sin 1, p1 = cos(−1); (p0³ + p1³, p0³ − p1³)
  EXPECT_POINT_NEAR(eval("ex", {0, 1}), 0.7535518418419491, 0.4380946313399621);
}

TEST(variations, julia_takes_either_square_root) {
  std::set<int> signs;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Point q = eval("julia", {0, 4}, 1, {}, {}, seed);  // √r = 2, θ/2 = 0
    EXPECT_NEAR(std::abs(q.x), 2, 1e-9);
    EXPECT_NEAR(q.y, 0, 1e-9);
    signs.insert(q.x > 0 ? 1 : -1);
  }
  EXPECT_EQ(signs.size(), 2u);
}

TEST(variations, bent_doubles_negative_x_and_halves_negative_y) {
  EXPECT_POINT_NEAR(eval("bent", {-1, -2}), -2, -1);
  EXPECT_POINT_NEAR(eval("bent", {1, 2}), 1, 2);
}

TEST(variations, waves_and_popcorn_read_the_affine_coefficients) {
  // waves: (x + b sin(y / c²), y + e sin(x / f²)) in the paper's order; here b = 0.5,
  // c (x translation) = 1, e (y's y coefficient) = 0.25, f (y translation) = 2.
  const AffineMap pre{.a = 1, .b = 0.5, .c = 0, .d = 0.25, .e = 1, .f = 2};
  EXPECT_POINT_NEAR(eval("waves", {2 * kPi, kPi / 2}, 1, {}, pre), 2 * kPi + 0.5, kPi / 2 + 0.25);
  // popcorn: (x + c sin(tan 3y), y + f sin(tan 3x)), c = 0.5, f = 0.25
  const AffineMap shift{.e = 0.5, .f = 0.25};
  EXPECT_POINT_NEAR(eval("popcorn", {0, kPi / 12}, 1, {}, shift), 0.42073549240394825, kPi / 12);
}

TEST(variations, fisheye_swaps_and_eyefish_does_not) {
  EXPECT_POINT_NEAR(eval("fisheye", {3, 4}), 4.0 / 3, 1);  // 2/(r + 1)·(y, x)
  EXPECT_POINT_NEAR(eval("eyefish", {3, 4}), 1, 4.0 / 3);
}

TEST(variations, exponential_power_cosine) {
  EXPECT_POINT_NEAR(eval("exponential", {1, 0.5}), 0, 1);  // e^0 (cos π/2, sin π/2)
  // r^sin θ (cos θ, sin θ) at (3, 4): 5^0.6 (0.8, 0.6)
  EXPECT_POINT_NEAR(eval("power", {3, 4}), 2.1012222435230137, 1.5759166826422601);
  EXPECT_POINT_NEAR(eval("cosine", {0.5, 1}), 0, -std::sinh(1.0));
}

TEST(variations, rings_and_fan_use_the_translation) {
  // rings, c = 1: ((r + 1) mod 2 − 1)(cos θ, sin θ) at (0, 0.5): 0.5·(1, 0)
  EXPECT_POINT_NEAR(eval("rings", {0, 0.5}, 1, {}, AffineMap{.e = 1}), 0.5, 0);
  // fan, c = 1: t = π; θ = 0 is in the first half: θ + π/2, r = 1
  EXPECT_POINT_NEAR(eval("fan", {0, 1}, 1, {}, AffineMap{.e = 1}), 0, 1);
}

TEST(variations, parametric_blob_pdj_rectangles) {
  // high 2, low 1, waves 1 at (1, 0): θ = π/2, r·(1 + (2 − 1)/2·(sin θ + 1)) = 2
  EXPECT_POINT_NEAR(eval("blob", {1, 0}, 1, {2, 1, 1}), 2, 0);
  EXPECT_POINT_NEAR(eval("blob", {0, 1}, 1, {2, 1, 1}), 0, 1.5);
  EXPECT_POINT_NEAR(eval("pdj", {0.5, 0.25}, 1, {1, 2, 3, 4}), -0.2928983466136168,
                    0.4571926807359147);
  EXPECT_POINT_NEAR(eval("rectangles", {0.3, 1.7}, 1, {1, 1}), 0.7, 1.3);
}

TEST(variations, bubble_cylinder_perspective_curl_ngon) {
  EXPECT_POINT_NEAR(eval("bubble", {2, 0}), 1, 0);          // 4/(r² + 4)
  EXPECT_POINT_NEAR(eval("cylinder", {kPi / 2, 3}), 1, 3);  // (sin x, y)
  // angle 1 quarter turn, dist 2 at (1, 1): 2/(2 − 1)·(x, y cos π/2)
  EXPECT_POINT_NEAR(eval("perspective", {1, 1}, 1, {1, 2}), 2, 0);
  EXPECT_POINT_NEAR(eval("curl", {1, 0}, 1, {1, 0}), 0.5, 0);  // z / (1 + z)
  // 4 sides, power 2, circle 1, corners 0: (x, y) / r²
  EXPECT_POINT_NEAR(eval("ngon", {2, 0}, 1, {4, 2, 1, 0}), 0.5, 0);
}

TEST(variations, tangent_cross_secant2) {
  EXPECT_POINT_NEAR(eval("tangent", {0, kPi / 4}), 0, 1);
  EXPECT_POINT_NEAR(eval("cross", {2, 1}), 2.0 / 3, 1.0 / 3);  // (x, y)/|x² − y²|
  // r = 0.5: (x, 1/cos(0.5) − 1)
  EXPECT_POINT_NEAR(eval("secant2", {0.5, 0}), 0.5, 0.13949392732454902);
}

TEST(variations, julian_lands_on_one_of_its_power_branches) {
  // power 2, dist 1 at (0, 4): φ = π/2, r^(1/2) = 2, angle (π/2 + 2πk)/2
  const double s = std::sqrt(2.0);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point q = eval("julian", {0, 4}, 1, {2, 1}, {}, seed);
    EXPECT_NEAR(std::abs(q.x), s, 1e-9);
    EXPECT_NEAR(q.y, q.x, 1e-9);
  }
}

TEST(variations, juliascope_mirrors_phi_on_odd_branches) {
  // power 2, dist 1 at (0, 4): branch 0 at φ/2 = π/4, branch 1 at (−φ + 2π)/2 = 3π/4; y > 0 on
  // both (a random sign, as the paper's Λ, would put half the points below the axis).
  const double s = std::sqrt(2.0);
  std::set<int> branches;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point q = eval("juliascope", {0, 4}, 1, {2, 1}, {}, seed);
    EXPECT_NEAR(std::abs(q.x), s, 1e-9);
    EXPECT_NEAR(q.y, s, 1e-9);
    branches.insert(q.x > 0);
  }
  EXPECT_EQ(branches.size(), 2u);
}

TEST(variations, rays_points_along_cos_x_sin_y) {
  // w² tan(Ψπw)/r² · (cos x, sin y), as flam3 draws it (the paper prints sin x)
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Point q = eval("rays", {0, kPi / 2}, 1, {}, {}, seed);  // (cos 0, sin π/2) = (1, 1)
    EXPECT_NEAR(q.x, q.y, 1e-9 * std::abs(q.x));
  }
}

TEST(variations, blur_stays_within_the_weight) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const Point q = eval("blur", {5, 5}, 0.5, {}, {}, seed);
    EXPECT_LE(std::hypot(q.x, q.y), 0.5 + 1e-12);
  }
}

}  // namespace
}  // namespace ifsfx::flame

namespace ifsfx::flame {
namespace {

// One batch form over `n` points, its draws taken from `rng` as the walker takes them (point by
// point, each point's draws in order); `floats`: its instance over float arrays (function_f, as
// an xform's sum runs a float form), the points rounded to float and the sums in float.
std::vector<double> run_batch(const detail::BatchVariation& b, const std::vector<double>& params,
                              const AffineMap& pre, const std::vector<double>& x,
                              const std::vector<double>& y, std::uint64_t seed,
                              bool floats = false) {
  using detail::kBatchStride;
  Rng rng(seed);
  std::vector<double> u(static_cast<std::size_t>(b.draws) * kBatchStride + kBatchStride);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < static_cast<std::size_t>(b.draws); ++j)
      u[j * kBatchStride + i] = rng.uniform();
  std::vector<double> px(kBatchStride), py(kBatchStride), ox(kBatchStride), oy(kBatchStride);
  std::copy(x.begin(), x.end(), px.begin());
  std::copy(y.begin(), y.end(), py.begin());
  const detail::BatchTerm t{.w = 0.7, .params = params.data(), .pre = &pre, .u = u.data()};
  if (floats) {
    std::vector<float> fx(px.begin(), px.end()), fy(py.begin(), py.end());
    std::vector<float> fox(kBatchStride), foy(kBatchStride);
    b.function_f(t, x.size(), fx.data(), fy.data(), fox.data(), foy.data());
    std::copy(fox.begin(), fox.end(), ox.begin());
    std::copy(foy.begin(), foy.end(), oy.begin());
  } else {
    b.function(t, x.size(), px.data(), py.data(), ox.data(), oy.data());
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < x.size(); ++i) out.insert(out.end(), {ox[i], oy[i]});
  return out;
}

// The values of a batch form's results further from the registry function's (drawing the same
// random numbers) than tol·(1 + |value|).
int far_from_registry(const detail::BatchVariation& b, const std::vector<double>& params,
                      const AffineMap& pre, const std::vector<double>& x,
                      const std::vector<double>& y, double tol, bool floats) {
  const Variation* v = find_variation(b.name);
  const std::vector<double> ours = run_batch(b, params, pre, x, y, 5, floats);
  Rng rng(5);
  int far = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Point r = v->function({.p = {x[i], y[i]}, .w = 0.7, .params = params, .pre = &pre}, rng);
    for (const auto& [got, want] : {std::pair{ours[2 * i], r.x}, std::pair{ours[2 * i + 1], r.y}})
      far += !(std::abs(got - want) <= tol * (1 + std::abs(want)));
  }
  return far;
}

// Every batch form (the chaos game's, flame/detail/batch_variations.h) gives its registry
// function's value at random points and parameters, drawing the same random numbers — to 1e-9 in
// double lanes, to 2e-4 in float lanes (their polynomials and the point's rounding to float) —
// and every level gives the scalar level's bits for each lane type (a float form's instance over
// float arrays too, the one an xform's sum runs). In float lanes 2 % of a
// form's values may be further: near its singular points a float rounding of the point moves the
// value by more (popcorn's and popcorn2's sin(tan(k·y)) near tan's poles, where sec²(k·y) > 3000
// on about 1.2 % of the points; cross's 1/|x² − y²| near x = ±y). A wrong form misses on most.
int far_allowed(detail::LaneType type, std::size_t values) {
  return type == detail::LaneType::f32 ? static_cast<int>(values / 50) : 0;
}

TEST(variations, batch_forms_equal_the_registry_and_every_level_the_scalar_bits) {
  Rng pick(99);
  const AffineMap pre{0.8, -0.3, 0.4, 0.9, 0.35, -0.6};
  for (const auto type : {detail::LaneType::f64, detail::LaneType::f32}) {
    const auto scalar = detail::batch_variations(CpuLevel::scalar, type);
    ASSERT_GE(scalar.size(), 40u);
    const double tol = type == detail::LaneType::f64 ? 1e-9 : 2e-4;
    for (const detail::BatchVariation& b : scalar) {
      const Variation* v = find_variation(b.name);
      ASSERT_NE(v, nullptr) << b.name;
      std::vector<double> params = default_parameters(*v);
      for (double& p : params) p += 0.25 + 0.5 * pick.uniform();
      std::vector<double> x, y;
      for (std::size_t i = 0; i < detail::kBatchLanes; ++i) {
        x.push_back(6 * pick.uniform() - 3);
        y.push_back(6 * pick.uniform() - 3);
      }
      const bool f32 = type == detail::LaneType::f32;
      ASSERT_EQ(f32, b.function_f != nullptr) << b.name;
      for (int pass = 0; pass < (f32 ? 2 : 1); ++pass) {
        const bool floats = pass == 1;
        EXPECT_LE(far_from_registry(b, params, pre, x, y, tol, floats),
                  far_allowed(type, 2 * x.size()))
            << b.name << (f32 ? " in float lanes" : "") << (floats ? " over floats" : "");
        const std::vector<double> ours = run_batch(b, params, pre, x, y, 5, floats);
        for (CpuLevel level : supported_cpu_levels()) {
          const detail::BatchVariation* other = detail::find_batch_variation(level, b.name, type);
          ASSERT_NE(other, nullptr) << b.name << " at " << to_string(level);
          const std::vector<double> theirs = run_batch(*other, params, pre, x, y, 5, floats);
          EXPECT_EQ(0, std::memcmp(theirs.data(), ours.data(), ours.size() * sizeof(double)))
              << b.name << " at " << to_string(level) << (floats ? " over floats" : "");
        }
      }
    }
  }
}

// super_shape with m = 0, as flam3-genome writes it, takes its radius factor once for the term
// (the random parameters above never give m = 0): still the registry's values, and every level
// the scalar bits, in both lane types.
TEST(variations, super_shape_of_m_0_equals_the_registry_at_every_level) {
  const AffineMap pre{1, 0, 0, 1, 0, 0};
  const std::vector<double> params = {0.18, 0, 39.3, 6.7, 6.7, 0.1};  // rnd m n1 n2 n3 holes
  Rng pick(7);
  std::vector<double> x, y;
  for (std::size_t i = 0; i < detail::kBatchLanes; ++i) {
    x.push_back(6 * pick.uniform() - 3);
    y.push_back(6 * pick.uniform() - 3);
  }
  for (const auto type : {detail::LaneType::f64, detail::LaneType::f32}) {
    const detail::BatchVariation* b =
        detail::find_batch_variation(CpuLevel::scalar, "super_shape", type);
    ASSERT_NE(b, nullptr);
    const bool f32 = type == detail::LaneType::f32;
    for (int pass = 0; pass < (f32 ? 2 : 1); ++pass) {
      const bool floats = pass == 1;
      EXPECT_EQ(far_from_registry(*b, params, pre, x, y, f32 ? 2e-4 : 1e-9, floats), 0);
      const std::vector<double> ours = run_batch(*b, params, pre, x, y, 5, floats);
      for (CpuLevel level : supported_cpu_levels()) {
        const std::vector<double> theirs =
            run_batch(*detail::find_batch_variation(level, "super_shape", type), params, pre, x, y,
                      5, floats);
        EXPECT_EQ(0, std::memcmp(theirs.data(), ours.data(), ours.size() * sizeof(double)))
            << to_string(level);
      }
    }
  }
}

}  // namespace
}  // namespace ifsfx::flame
