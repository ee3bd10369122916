// SPDX-License-Identifier: Apache-2.0
// flam3's variations after the paper's 49, the complex functions, and the ones beyond flam3, at
// points where their published formulas are worked by hand (values of the complex functions from
// the functions themselves: w·f(z) at z = 0.5 + 0.25i).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "flame/detail/simplex_noise.h"
#include "variation_check.h"

namespace ifsfx::flame {
namespace {

using test::eval;
constexpr double kPi = std::numbers::pi;

TEST(variations_flam3, disc2_bipolar_butterfly_cell) {
  // rot 0, twist 0 at (1, 0): r = w·θ/π = 1/2, t = 0: ((sin 0 + 0)·r, (cos 0 + 0)·r)
  EXPECT_POINT_NEAR(eval("disc2", {1, 0}, 1, {0, 0}), 0, 0.5);
  // (0, 0.5): u = ln(1.25/1.25)/4 = 0, v = atan2(1, −0.75)/2, both × 2/π
  EXPECT_POINT_NEAR(eval("bipolar", {0, 0.5}, 1, {0}), 0, 0.7048327646991335);
  // (1, 0.5): 4/√(3π)·√(|xy|/(x² + (2y)²))·(x, 2y)
  EXPECT_POINT_NEAR(eval("butterfly", {1, 0.5}), 0.6514700158705599, 0.6514700158705599);
  // size 1 at (0.25, 1.5): cell (0, 1) → (0, 2), offset (0.25, 0.5): (0.25, −2.5)
  EXPECT_POINT_NEAR(eval("cell", {0.25, 1.5}, 1, {1}), 0.25, -2.5);
}

TEST(variations_flam3, cpow_escher_and_mobius_are_complex_maps) {
  // cpow r = 2, i = 0, power 1: z², one branch
  EXPECT_POINT_NEAR(eval("cpow", {0.5, 0.25}, 1, {2, 0, 1}), 0.1875, 0.25);
  EXPECT_POINT_NEAR(eval("escher", {0.5, 0.25}, 1, {0}), 0.5, 0.25);  // β = 0: z
  // ((1 + i)z + 1)/(z + 2)
  EXPECT_POINT_NEAR(eval("mobius", {0.5, 0.25}, 1, {1, 1, 1, 0, 1, 0, 2, 0}), 0.5247524752475248,
                    0.24752475247524752);
  EXPECT_POINT_NEAR(eval("Mobius", {0.5, 0.25}, 1, {1, 1, 1, 0, 1, 0, 2, 0}), 0.5247524752475248,
                    0.24752475247524752);
}

TEST(variations_flam3, curve_waves2_popcorn2_stripes) {
  EXPECT_POINT_NEAR(eval("curve", {0.3, 0.4}, 1, {1, 0.5, 1, 2}), 1.1521437889662114,
                    0.8888756185966682);
  EXPECT_POINT_NEAR(eval("waves2", {0.1, 0.2}, 1, {0.5, 0.25, 2, 3}), 0.29470917115432527,
                    0.2738800516653349);
  EXPECT_POINT_NEAR(eval("popcorn2", {0.1, 0.2}, 1, {0.5, 0.25, 3}), 0.4160021519178251,
                    0.2761066143780162);
  EXPECT_POINT_NEAR(eval("stripes", {1.3, 0.2}, 1, {0.5, 2}), 1.15, 0.38);
}

TEST(variations_flam3, separation_splits_split_modulus_bent2) {
  EXPECT_POINT_NEAR(eval("separation", {1, -1}, 1, {1, 0.5, 2, 0}), 0.9142135623730951,
                    -2.23606797749979);
  EXPECT_POINT_NEAR(eval("splits", {1, -1}, 1, {0.5, 0.25}), 1.5, -1.25);
  // cos(0.75π) < 0 flips y; cos(0.25π) > 0 keeps x
  EXPECT_POINT_NEAR(eval("split", {0.75, 0.25}, 1, {1, 1}), 0.75, -0.25);
  EXPECT_POINT_NEAR(eval("modulus", {1.5, -0.25}, 1, {1, 1}), -0.5, -0.25);
  EXPECT_POINT_NEAR(eval("bent2", {-1, -1}, 1, {2, 3}), -2, -3);
}

TEST(variations_flam3, wedge_whorl_scry_loonie_lazysusan) {
  EXPECT_POINT_NEAR(eval("wedge", {3, 4}, 1, {0, 0.5, 1, 0}), 3.3, 4.4);  // (r + hole)·(cos, sin)
  // inside the circle of radius w = 2: the angle turns by inside/(w − r) = 0.5
  EXPECT_POINT_NEAR(eval("whorl", {0.6, 0.8}, 2, {0.5, 0}), 0.2860182125017223, 1.97944274534964);
  EXPECT_POINT_NEAR(eval("scry", {3, 4}), 3.0 / 130, 4.0 / 130);  // 1/(r·(r² + 1/w))
  EXPECT_POINT_NEAR(eval("loonie", {0.3, 0.4}), 0.3 * std::sqrt(3.0), 0.4 * std::sqrt(3.0));
  EXPECT_POINT_NEAR(eval("loonie", {3, 4}, 0.5), 1.5, 2);  // outside: linear
  EXPECT_POINT_NEAR(eval("lazysusan", {0.3, 0.4}, 1, {1, 0, 0, 0, 0}), -0.1744977021627167,
                    0.4685622177896248);
}

TEST(variations_flam3, auger_flux_elliptic_foci_polar2_oscilloscope) {
  EXPECT_POINT_NEAR(eval("auger", {0.5, 0.25}, 1, {1, 0.5, 1, 1}), 0.6237019796272615,
                    0.4297845769765761);
  EXPECT_POINT_NEAR(eval("flux", {0, 1}, 1, {0}), std::sqrt(2.0), std::sqrt(2.0));
  EXPECT_POINT_NEAR(eval("elliptic", {0, 0.5}), 0, 0.24161510933030436);
  EXPECT_POINT_NEAR(eval("foci", {1, 0}), 2.163953413738653, 0);
  EXPECT_POINT_NEAR(eval("polar2", {0, 2}), 0, 0.2206356001526516);  // (θ/π, ln r²/2π)
  // sep 1, freq 0.25, amp 1: under the trace at x = 0 (t = 2) y flips; at x = 2 (t = 0) not
  EXPECT_POINT_NEAR(eval("oscilloscope", {0, 0.5}, 1, {1, 0.25, 1, 0}), 0, -0.5);
  EXPECT_POINT_NEAR(eval("oscilloscope", {2, 0.5}, 1, {1, 0.25, 1, 0}), 2, 0.5);
}

TEST(variations_flam3, super_shape_with_unit_exponents) {
  // rnd 0, m 0, n1 = n2 = n3 = 1: θ = π/4, (|cos| + |sin|)^−1 = 1/√2 scales the point
  EXPECT_POINT_NEAR(eval("super_shape", {3, 4}, 1, {0, 0, 1, 1, 1, 0}), 2.1213203435596424,
                    2.82842712474619);
}

TEST(variations_flam3, random_ones_stay_on_their_curves) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point f = eval("flower", {3, 0}, 1, {2, 0}, {}, seed);  // (Ψ·cos 2φ / r)·(x, y)
    EXPECT_NEAR(f.y, 0, 1e-12);
    EXPECT_TRUE(f.x >= 0 && f.x < 1);
    const Point p = eval("parabola", {kPi / 2, 0}, 1, {1, 1}, {}, seed);  // (Ψ sin² r, Ψ cos r)
    EXPECT_NEAR(p.y, 0, 1e-12);
    EXPECT_TRUE(p.x >= 0 && p.x < 1);
    const Point c = eval("conic", {3, 4}, 1, {1, 0}, {}, seed);  // along (3, 4), ≤ 1/1.6
    EXPECT_NEAR(c.x * 4, c.y * 3, 1e-12);
    EXPECT_LE(std::hypot(c.x, c.y), 1 / 1.6 + 1e-12);
    const Point b = eval("pre_blur", {9, 9}, 0.5, {}, {}, seed);  // a Gaussian offset, |.| ≤ 2w
    EXPECT_LE(std::hypot(b.x, b.y), 1 + 1e-12);
  }
}

TEST(variations_complex, are_w_times_the_complex_function) {
  const Point z{0.5, 0.25};
  EXPECT_POINT_NEAR(eval("exp", z), 1.5974665191199127, 0.4079001700783598);
  EXPECT_POINT_NEAR(eval("log", z), -0.5815754049028404, 0.4636476090008061);
  EXPECT_POINT_NEAR(eval("sin", z), 0.494485780933195, 0.22168816414957482);
  EXPECT_POINT_NEAR(eval("cos", z), 0.9051501505596068, -0.12110879604381165);
  EXPECT_POINT_NEAR(eval("tan", z), 0.504500702698564, 0.31242069250258875);
  EXPECT_POINT_NEAR(eval("sec", z), 1.085358604751614, 0.14522062866143562);
  EXPECT_POINT_NEAR(eval("csc", z), 1.6838612682157232, -0.7549097014050444);
  EXPECT_POINT_NEAR(eval("cot", z), 1.432721075387994, -0.8872370407840957);
  EXPECT_POINT_NEAR(eval("sinh", z), 0.504895714387995, 0.2789791283502615);
  EXPECT_POINT_NEAR(eval("cosh", z), 1.0925708047319176, 0.12892104172809826);
  EXPECT_POINT_NEAR(eval("tanh", z), 0.4854872810241353, 0.19805544995134958);
  EXPECT_POINT_NEAR(eval("sech", z), 0.902703693945398, -0.10651712464877593);
  EXPECT_POINT_NEAR(eval("csch", z), 1.51734688627714, -0.8384070208472441);
  // flam3 draws the conjugate of coth z (tests/flame/variations_vs_flam3 shows it)
  EXPECT_POINT_NEAR(eval("coth", z), 1.7658972151170622, 0.7204010922182281);
  EXPECT_POINT_NEAR(eval("sin", z, 2), 2 * 0.494485780933195, 2 * 0.22168816414957482);
}

TEST(variations_more, three_d_ones_are_planar_no_ops_or_their_z0_slice) {
  for (const char* name : {"flatten", "zscale", "ztranslate", "zcone", "zblur"}) {
    EXPECT_EQ(find_variation(name)->kind, VariationKind::flat_3d) << name;
    EXPECT_POINT_NEAR(eval(name, {3, 4}), 0, 0);
  }
  EXPECT_POINT_NEAR(eval("linear3D", {3, 4}, 0.5), 1.5, 2);
  EXPECT_POINT_NEAR(eval("Spherical3D", {3, 4}), 0.12, 0.16);       // (x, y)/r²
  EXPECT_POINT_NEAR(eval("hemisphere", {2, 2}), 2.0 / 3, 2.0 / 3);  // (x, y)/√(r² + 1)
}

TEST(variations_more, julia3D_epispiral_and_the_blurs) {
  // power 2 at (0, 4): r^(1/2) = 2 at angle (π/2 + 2πk)/2, as julian
  const Point j = eval("julia3D", {0, 4}, 1, {2});
  EXPECT_NEAR(std::abs(j.x), std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(j.y, j.x, 1e-9);
  // n 6, thickness 0, holes 1 at (1, 0): θ = 0, t = −1 + 1/cos 0 = 0
  EXPECT_POINT_NEAR(eval("epispiral", {1, 0}, 1, {6, 0, 1}), 0, 0);
  // n 1, holes 0 at (1, 1): θ = π/4, t = √2: (1, 1)
  EXPECT_POINT_NEAR(eval("epispiral", {1, 1}, 1, {1, 0, 0}), 1, 1);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point s = eval("sineblur", {5, 5}, 1, {1}, {}, seed);  // radius acos(2Ψ − 1)/π ≤ 1
    EXPECT_LE(std::hypot(s.x, s.y), 1 + 1e-12);
    const Point c = eval("blur_circle", {5, 5}, 1, {}, {}, seed);
    EXPECT_LE(std::hypot(c.x, c.y), 1 + 1e-12);
    const Point l = eval("blur_linear", {1, 1}, 1, {2, kPi / 2}, {}, seed);  // up by [0, 2)
    EXPECT_NEAR(l.x, 1, 1e-12);
    EXPECT_TRUE(l.y >= 1 && l.y < 3);
    const Point z = eval("blur_zoom", {1, 2}, 1, {1, 0, 0}, {}, seed);  // (1, 2)·[1, 2)
    EXPECT_NEAR(z.y, 2 * z.x, 1e-12);
    EXPECT_TRUE(z.x >= 1 && z.x < 2);
  }
}

TEST(variations_packs, falloff2_leaves_points_within_mindist_and_blurs_by_distance) {
  // (0.3, 0.4): d = 0.5 = mindist, dist = 0: w·p whatever the type and the draws
  for (double type : {0, 1, 2})
    EXPECT_POINT_NEAR(eval("falloff2", {0.3, 0.4}, 2, {1, 0.5, 1, 1, 0, 0, 0, 0, 0, 0, type}), 0.6,
                      0.8);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // (3, 4), type 0: dist = (5 − 0.5)·0.04 = 0.18, each coordinate moved by u·0.18, |u| ≤ ½
    const Point l = eval("falloff2", {3, 4}, 1, {}, {}, seed);
    EXPECT_LE(std::abs(l.x - 3), 0.09 + 1e-12);
    EXPECT_LE(std::abs(l.y - 4), 0.09 + 1e-12);
    // type 1, mul_x 0: the radius stays 5, the angle moves by at most 0.09
    const Point r = eval("falloff2", {3, 4}, 1, {1, 0.5, 0, 1, 0, 0, 0, 0, 0, 0, 1}, {}, seed);
    EXPECT_NEAR(std::hypot(r.x, r.y), 5, 1e-9);
    EXPECT_LE(std::abs(std::atan2(r.y, r.x) - std::atan2(4.0, 3.0)), 0.09 + 1e-12);
    // a type of 0.6 is type 1: whole-number parameters are rounded, as Ember reads them
    const Point r6 = eval("falloff2", {3, 4}, 1, {1, 0.5, 0, 1, 0, 0, 0, 0, 0, 0, 0.6}, {}, seed);
    EXPECT_EQ(r6.x, r.x);
    EXPECT_EQ(r6.y, r.y);
    // invert at the origin, mindist 0: dist = max(1 − 0, 0)·0.04, offsets within ±0.02
    const Point i = eval("falloff2", {0, 0}, 1, {1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 0}, {}, seed);
    EXPECT_LE(std::max(std::abs(i.x), std::abs(i.y)), 0.02 + 1e-12);
  }
}

TEST(variations_packs, bwraps_magnifies_a_bubble_about_each_cell_centre) {
  // cellsize 1, space 0: bubbles of radius ½ about (k + ½, l + ½); g² = 1 + 10⁻⁶
  EXPECT_POINT_NEAR(eval("bwraps", {2.5, -0.5}), 2.5, -0.5);    // a centre stays
  EXPECT_POINT_NEAR(eval("bwraps", {0.95, 0.95}), 0.95, 0.95);  // |l|² = 0.405 > ¼: outside
  // (0.7, 0.5): l = (0.2, 0); max bubble m = g²/2/(g⁴/16 + 1), f = ½/m/((0.2g²)²/4 + 1)
  const double g2 = 1 + 1e-6, m = g2 / 2 / (g2 * g2 / 16 + 1);
  const double lx = 0.2 * g2 * 0.5 / m / (0.01 * g2 * g2 + 1);
  EXPECT_POINT_NEAR(eval("bwraps", {0.7, 0.5}), 0.5 + lx, 0.5);
  // inner twist π/2: θ = π/2·(1 − lx²/¼), l turned clockwise by θ
  const double th = kPi / 2 * (1 - 4 * lx * lx);
  EXPECT_POINT_NEAR(eval("bwraps", {0.7, 0.5}, 1, {1, 0, 1, kPi / 2, 0}), 0.5 + std::cos(th) * lx,
                    0.5 - std::sin(th) * lx);
  EXPECT_POINT_NEAR(eval("bwraps", {0.7, 0.5}, 2, {0}), 1.4, 1);  // cellsize 0: w·p
}

TEST(variations_packs, unpolar_and_curl3D) {
  // w/(2π)·e^y·(sin x, cos x)
  EXPECT_POINT_NEAR(eval("unpolar", {kPi / 2, 0}), 1 / (2 * kPi), 0);
  EXPECT_POINT_NEAR(eval("unpolar", {0, std::log(2.0)}, 2), 0, 2 / kPi);
  // cx 1 at (1, 0): (1 + 1)/(1 + 2 + 1); cy 1 at (0, −1): (−1 − 1)/(1 + 2 + 1)
  EXPECT_POINT_NEAR(eval("curl3D", {1, 0}, 1, {1, 0, 0}), 0.5, 0);
  EXPECT_POINT_NEAR(eval("curl3D", {0, -1}, 1, {0, 1, 0}), 0, -0.5);
  EXPECT_POINT_NEAR(eval("curl3D", {1, 0}, 1, {0, 0, 1}), 0.5, 0);  // cz: 1/(r²·1 + 1)
}

TEST(variations_packs, glynnia_takes_one_of_its_two_roots) {
  // (2, 0), r = 2 > 1: √(r + x)·√2/2 = √2, or (r + x)/√(r·(r + x)²) = 1/√2
  // (0.5, 0), r ≤ 1, x mirrored: −√2/2, or −1/√(0.5) = −√2
  std::set<long> seen;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const Point a = eval("glynnia", {2, 0}, 1, {}, {}, seed);
    EXPECT_TRUE(std::abs(a.x - std::sqrt(2.0)) < 1e-9 || std::abs(a.x - std::sqrt(0.5)) < 1e-9)
        << a.x;
    const Point b = eval("glynnia", {0.5, 0}, 1, {}, {}, seed);
    EXPECT_TRUE(std::abs(b.x + std::sqrt(0.5)) < 1e-9 || std::abs(b.x + std::sqrt(2.0)) < 1e-9)
        << b.x;
    EXPECT_NEAR(a.y, 0, 1e-12);
    seen.insert(std::lround(a.x * 1000));
  }
  EXPECT_EQ(seen.size(), 2u);
}

TEST(variations_packs, tile_log_and_tile_hlp_move_whole_tiles) {
  std::set<long> tiles, hlp;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Point t = eval("tile_log", {0.25, 3}, 1, {}, {}, seed);  // x + round(±ln U)
    EXPECT_NEAR(t.x - 0.25, std::round(t.x - 0.25), 1e-12);
    EXPECT_NEAR(t.y, 3, 1e-12);
    tiles.insert(std::lround(t.x - 0.25));
    EXPECT_POINT_NEAR(eval("tile_log", {0.25, 3}, 1, {0}, {}, seed), 0.25, 3);  // spread 0
    // width 1 at x = ½: cos(π/2) = 0 < 2Ψ − 1 half the time: ½ or ½ − 1
    const Point h = eval("tile_hlp", {0.5, 2}, 1, {}, {}, seed);
    EXPECT_TRUE(std::abs(h.x - 0.5) < 1e-12 || std::abs(h.x + 0.5) < 1e-12) << h.x;
    hlp.insert(std::lround(h.x * 2));
    EXPECT_POINT_NEAR(eval("tile_hlp", {-2, 2}, 1, {}, {}, seed), -2, 2);  // f = 0: never
  }
  EXPECT_GE(tiles.size(), 3u);  // 0 and tiles on both sides
  EXPECT_EQ(hlp.size(), 2u);
}

TEST(variations_packs, twoface_hypertile2_gaussian) {
  EXPECT_POINT_NEAR(eval("twoface", {2, 0}), 0.5, 0);     // x > 0: (x, y)/r²
  EXPECT_POINT_NEAR(eval("twoface", {-2, 1}, 2), -4, 2);  // x ≤ 0: w·p
  // p 3, q 7: a = 2π/3, cos a = −½, R = 1/√(1 + 1.5/(cos(2π/7) − ½)); 0 ↦ R, turned by −k·a
  const double big_r = 1 / std::sqrt(1 + 1.5 / (std::cos(2 * kPi / 7) - 0.5));
  std::set<long> turns;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const Point h = eval("hypertile2", {0, 0}, 1, {}, {}, seed);
    EXPECT_NEAR(std::hypot(h.x, h.y), big_r, 1e-9);
    const double k = std::atan2(h.y, h.x) / (2 * kPi / 3);
    EXPECT_NEAR(k, std::round(k), 1e-9);
    turns.insert(std::lround(k));
    const Point g = eval("gaussian", {3, 4}, 0.5, {}, {}, seed);  // p + offset ≤ 2w
    EXPECT_LE(std::hypot(g.x - 3, g.y - 4), 1 + 1e-12);
  }
  EXPECT_EQ(turns.size(), 3u);  // −1, 0, 1: the three turns of the triangle
  EXPECT_POINT_NEAR(eval("gaussian", {3, 4}, 0), 3, 4);
}

TEST(variations_packs, bTransform_is_the_identity_through_bipolar_coordinates_at_power_1) {
  // (0, 1): τ = ½(ln 2 − ln 2) = 0, σ = π − π/4 − π/4 = π/2: (sinh 0, sin π/2)/(cosh 0 − 0)
  EXPECT_POINT_NEAR(eval("bTransform", {0, 1}), 0, 1);
  // (0.5, 0): τ = ½ ln(2.25/0.25) = ln 3, σ = π: sinh(ln 3)/(cosh(ln 3) + 1) = (4/3)/(8/3)
  EXPECT_POINT_NEAR(eval("bTransform", {0.5, 0}), 0.5, 0);
  // move ln 2 at (0, 1): τ = ln 2, sinh τ = 0.75, cosh τ = 1.25: (0.75, 1)/1.25
  EXPECT_POINT_NEAR(eval("bTransform", {0, 1}, 1, {0, 1, std::log(2.0), 0}), 0.6, 0.8);
  // power 2 at (0, 1): τ = 0, σ = π/4 or 5π/4: y = sin σ/(1 − cos σ) = 1 + √2 or 1 − √2
  std::set<long> branches;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point b = eval("bTransform", {0, 1}, 1, {0, 2, 0, 0}, {}, seed);
    EXPECT_NEAR(b.x, 0, 1e-12);
    EXPECT_TRUE(std::abs(b.y - 1 - std::sqrt(2.0)) < 1e-9 ||
                std::abs(b.y - 1 + std::sqrt(2.0)) < 1e-9)
        << b.y;
    branches.insert(b.y > 0);
  }
  EXPECT_EQ(branches.size(), 2u);
}

TEST(variations_packs, crop_puts_points_back_into_its_rectangle) {
  EXPECT_POINT_NEAR(eval("crop", {0.5, 0.5}, 2), 1, 1);  // inside [−1, 1]²: w·p
  EXPECT_POINT_NEAR(eval("crop", {3, 0.5}), 1, 0.5);     // scatter 0: onto the edge x = 1
  EXPECT_POINT_NEAR(eval("crop", {3, 0.5}, 1, {0, -1, 1, -1, 1, 1}), 0, 0);  // zero: the origin
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // scatter 1: moved in from the edge by Ψ·(half the side) = Ψ·1
    const Point c = eval("crop", {3, -5}, 1, {1, -1, 1, -1, 1, 0}, {}, seed);
    EXPECT_TRUE(c.x > 0 && c.x <= 1) << c.x;
    EXPECT_TRUE(c.y >= -1 && c.y < 0) << c.y;
  }
}

// crackle reads no point: it draws u = b·(sin θ, cos θ), b = (Ψ1 + Ψ2)/2 + (Ψ3 − ½)/4, θ = 2πΨ4,
// from the walker's generator, which the test replays with the same seed.
Point crackle_draw(std::uint64_t seed) {
  Rng rng(seed);
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform(), u4 = rng.uniform();
  const double b = (u1 + u2) / 2 + (u3 - 0.5) / 4, theta = 2 * kPi * u4;
  return {b * std::sin(theta), b * std::cos(theta)};
}

TEST(variations_packs2, crackle_moves_its_draw_within_square_cells_without_distortion) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point u = crackle_draw(seed);
    // power 1, scale 1: L^1/L = 1, u itself whatever the cells; w = 2 doubles it
    EXPECT_POINT_NEAR(eval("crackle", {9, 9}, 2, {1, 1, 0.7, 1, 0}, {}, seed), 2 * u.x, 2 * u.y);
    // cellsize 1, distort 0: centres on the lattice s·(i, j), s = ½, the cells squares of side
    // ½ about them. Scale 0: the centre nearest u, round(2u)/2.
    const Point c{std::round(2 * u.x) / 2, std::round(2 * u.y) / 2};
    EXPECT_POINT_NEAR(eval("crackle", {9, 9}, 1, {1, 0.2, 0, 0, 0}, {}, seed), c.x, c.y);
    // Power 0, scale 1: u − c divided by its level L = 2·max(|dx|, |dy|)/s (the nearest
    // neighbour's bisector at s/2): onto the cell's edge, on the ray from c through u.
    const double dx = u.x - c.x, dy = u.y - c.y, level = 4 * std::max(std::abs(dx), std::abs(dy));
    EXPECT_POINT_NEAR(eval("crackle", {9, 9}, 1, {1, 0, 0, 1, 0}, {}, seed), c.x + dx / level,
                      c.y + dy / level);
  }
  EXPECT_POINT_NEAR(eval("crackle", {9, 9}, 1, {0}), 0, 0);  // cellsize 0: no cells, nothing
}

TEST(variations_packs2, crackle_distorts_its_centres_by_a_bounded_noise) {
  // The simplex noise is 0 at a lattice corner (its own offset 0, the other corners' offsets
  // |d|² = (5/6)² + 2·(1/6)² = 0.75 > 0.6 out of reach) and stays within [−1, 1].
  EXPECT_EQ(detail::simplex_noise(0, 0, 0), 0);
  EXPECT_EQ(detail::simplex_noise(1, 2, -3), 0);  // skewed: (1, 2, −3) + 0 is a corner too
  double lo = 0, hi = 0;
  for (int i = 0; i < 2000; ++i) {
    const double n = detail::simplex_noise(0.37 * i, 0.11 * i - 5, 0.05 * i);
    lo = std::min(lo, n);
    hi = std::max(hi, n);
  }
  EXPECT_TRUE(lo > -1.1 && lo < -0.3 && hi < 1.1 && hi > 0.3) << lo << " " << hi;
  // distort 1, scale 0: the centre of u's cell, s·(i + n(2.5i, 2.5j, 0), j + n(2.5j + 30.2,
  // 2.5i − 12.1, 19.8)), s = ½, of the cell (i, j) whose centre is the nearest to u
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Point u = crackle_draw(seed);
    const Point got = eval("crackle", {9, 9}, 1, {1, 0.2, 1, 0, 0}, {}, seed);
    double best = 1e9;
    Point nearest{};
    for (int i = -6; i <= 6; ++i)
      for (int j = -6; j <= 6; ++j) {
        const Point c{(i + detail::simplex_noise(2.5 * i, 2.5 * j, 0)) / 2,
                      (j + detail::simplex_noise(2.5 * j + 30.2, 2.5 * i - 12.1, 19.8)) / 2};
        const double d = std::hypot(c.x - u.x, c.y - u.y);
        if (d < best) best = d, nearest = c;
      }
    EXPECT_POINT_NEAR(got, nearest.x, nearest.y);
  }
}

TEST(variations_packs2, hexes_scales_and_turns_within_hexagonal_cells) {
  // cellsize 1: centres (3/2·(a − b), √3/2·(a + b)), six neighbours √3 away; at (0.3, 0) in the
  // cell of the origin, the level is 2·(0.3·1.5)/3 = 0.3 (the neighbours (1.5, ±√3/2)).
  EXPECT_POINT_NEAR(eval("hexes", {0.3, 0}, 1, {1, 1, 0, 1}), 0.3, 0);   // power 1: p
  EXPECT_POINT_NEAR(eval("hexes", {0.3, 0}, 1, {1, 2, 0, 1}), 0.09, 0);  // level 0.3²
  EXPECT_POINT_NEAR(eval("hexes", {0.2, 0}, 2, {1, 1, 0, 2}), 0.8, 0);   // scale 2, w 2
  const double r3 = std::sqrt(3.0);
  EXPECT_POINT_NEAR(eval("hexes", {1.6, r3 / 2 - 0.1}, 1, {1, 1, 0, 1}), 1.6, r3 / 2 - 0.1);
  // rotate ¼: a quarter turn clockwise about the centre, (0.1, 0) → (0, −0.1); levels 0.1 and
  // 2·(0.1·√3)/3 < ½, so the scale is L1^1/L1 = 1
  EXPECT_POINT_NEAR(eval("hexes", {0.1, 0}, 1, {1, 1, 0.25, 1}), 0, -0.1);
  // about the centre (0, √3) of cell (1, 1): (0.1, √3) → (0, √3 − 0.1)
  EXPECT_POINT_NEAR(eval("hexes", {0.1, r3}, 1, {1, 1, 0.25, 1}), 0, r3 - 0.1);
}

TEST(variations_packs2, smartcrop_cuts_to_a_polygon_and_puts_cut_points_on_its_border) {
  // power 4, radius 1: the square [−1, 1]² (apothem 1, its sides' middles at −π, −π/2, 0, π/2)
  EXPECT_POINT_NEAR(eval("smartcrop", {0.5, -0.5}, 2), 1, -1);  // inside: w·p
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 0}), 1, 0);           // onto the border, same angle
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 2}), 1, 1);           // a corner: 1/cos(π/4)
  EXPECT_POINT_NEAR(eval("smartcrop", {3, 1}), 1, 1.0 / 3);     // the side x = 1
  EXPECT_POINT_NEAR(eval("smartcrop", {-3, -4}, 1, {4, 1, 0, 1, 0}), -0.6, -0.8);  // circle
  // offset ½ (scatter 0): outside the border by coeff·½; crop mode 0: the origin
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 0}, 1, {4, 1, 0, 1, 1, 0, 0, 0.5}), 1.5, 0);
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 0}, 1, {4, 1, 0, 1, 1, 0, 0, 0, 0, 0}), 0, 0);
  // crop mode −1, rotation 1: the radius kept, turned by α = π/2
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 0}, 1, {4, 1, 0, 1, 1, 0, 0, 0, 1, -1}), 0, 2);
  // radius −½: the inside cut, (0.1, 0) put out on x = ½, (2, 0) kept
  EXPECT_POINT_NEAR(eval("smartcrop", {0.1, 0}, 1, {4, -0.5}), 0.5, 0);
  EXPECT_POINT_NEAR(eval("smartcrop", {2, 0}, 1, {4, -0.5}), 2, 0);
  // roundstr 1: the corner at π/4 pulled in to coeff = (1 − c)·√2 + c, c = 2/(4·sin(π/4)) =
  // 1/√2, i.e. to (1.5 − 1/√2)·(1, 1)
  const double k = 1.5 - 1 / std::sqrt(2.0);
  EXPECT_POINT_NEAR(eval("smartcrop", {3, 3}, 1, {4, 1, 1}), k, k);
  // crop mode 2 (onto the last point kept, a state): not a number, the walker starts again
  EXPECT_TRUE(std::isnan(eval("smartcrop", {2, 0}, 1, {4, 1, 0, 1, 1, 0, 0, 0, 0, 2}).x));
}

TEST(variations_packs2, smartcrop_below_power_2_cuts_a_sector) {
  // power 1, radius 1: the upper half plane [0, π] kept; a cut point keeps its radius and goes
  // to one of the two edges of the sector, angle 0 or π
  std::set<long> ends;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    EXPECT_POINT_NEAR(eval("smartcrop", {0.3, 2}, 1, {1, 1}, {}, seed), 0.3, 2);
    const Point c = eval("smartcrop", {0, -2}, 1, {1, 1}, {}, seed);
    EXPECT_NEAR(std::abs(c.x), 2, 1e-12);
    EXPECT_NEAR(c.y, 0, 1e-12);
    ends.insert(std::lround(c.x));
  }
  EXPECT_EQ(ends.size(), 2u);
}

TEST(variations_packs3, mirrors_and_rotations_are_planar_slices) {
  std::set<long> signs;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // ±|x|, y; the weight only switches it on (0.05 as one of the packs' flames writes)
    const Point m = eval("mirror_x", {-3, 2}, 0.05, {}, {}, seed);
    EXPECT_NEAR(std::abs(m.x), 3, 1e-12);
    EXPECT_NEAR(m.y, 2, 1e-12);
    signs.insert(std::lround(m.x));
    const Point n = eval("mirror_y", {-3, 2}, 1, {}, {}, seed);
    EXPECT_POINT_NEAR(n, -3, m.x > 0 ? 2 : -2);  // the same draw: the same sign
  }
  EXPECT_EQ(signs.size(), 2u);
  // the turn by w·π/2 about x (y) at z = 0: y (x) times cos(w·π/2); w = ⅔: cos(π/3) = ½
  EXPECT_POINT_NEAR(eval("rotate_x", {2, 3}, 2.0 / 3), 2, 1.5);
  EXPECT_POINT_NEAR(eval("rotate_y", {2, 3}, 2.0 / 3), 1, 3);
  EXPECT_POINT_NEAR(eval("rotate_y", {2, 3}, 1), 0, 3);  // a quarter turn: x seen edge on
}

TEST(variations_packs3, circlecrop_and_bcircle_keep_a_disc) {
  EXPECT_POINT_NEAR(eval("circlecrop", {0.3, 0.4}, 2), 0.6, 0.8);  // inside: w·p
  EXPECT_POINT_NEAR(eval("circlecrop", {3, 4}), 0, 0);             // outside, zero: the origin
  // centre (1, 1), zero 0, scatter 0: d = (3, 4) → w·1·(0.6, 0.8) + (1, 1)
  EXPECT_POINT_NEAR(eval("circlecrop", {4, 5}, 1, {1, 1, 1, 0, 0}), 1.6, 1.8);
  // bcircle scale 2: (0.3, 0.4) → (0.6, 0.8), on the unit circle: kept
  EXPECT_POINT_NEAR(eval("bcircle", {0.3, 0.4}, 1, {2, 0}), 0.6, 0.8);
  EXPECT_POINT_NEAR(eval("bcircle", {3, 4}, 1, {1, 0}), 0, 0);  // no border: the origin
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // scatter 1: radius 1 + Ψ/2 on d's ray; bcircle border 5: 1 + Ψ on q's ray
    const Point c = eval("circlecrop", {4, 5}, 1, {1, 1, 1, 1, 0}, {}, seed);
    const double rc = std::hypot(c.x - 1, c.y - 1);
    EXPECT_TRUE(rc >= 1 && rc < 1.5) << rc;
    EXPECT_NEAR((c.y - 1) / (c.x - 1), 4.0 / 3, 1e-9);
    const Point b = eval("bcircle", {3, 4}, 1, {1, 5}, {}, seed);
    const double rb = std::hypot(b.x, b.y);
    EXPECT_TRUE(rb >= 1 && rb < 2) << rb;
    EXPECT_NEAR(b.y / b.x, 4.0 / 3, 1e-9);
  }
}

TEST(variations_packs3, shredlin_gnarly_bubble2_wdisc) {
  // x = 1.25: n = 1, f = ¼: ¼·½ + 1 + ½·½ = 1.375; y = −¼: n = 0, f = −¼: −⅛ − ¼
  EXPECT_POINT_NEAR(eval("shredlin", {1.25, -0.25}), 1.375, -0.375);
  EXPECT_POINT_NEAR(eval("shredlin", {1.25, -0.25}, 1, {1, 1, 1, 1}), 1.25, -0.25);  // width 1
  // gnarly: a cell's centre and its rim stay; (0.75, 0.5), l = (¼, 0) about (½, ½), |l|²/¼ =
  // ¼: turned clockwise by ln ¼, i.e. anticlockwise by ln 4
  EXPECT_POINT_NEAR(eval("gnarly", {0.5, 0.5}), 0.5, 0.5);
  EXPECT_POINT_NEAR(eval("gnarly", {1, 0.5}), 1, 0.5);
  const double t = std::log(4.0);
  EXPECT_POINT_NEAR(eval("gnarly", {0.75, 0.5}), 0.5 + 0.25 * std::cos(t),
                    0.5 + 0.25 * std::sin(t));
  // bubble2: w·(x·bx, y·by)/(r²/4 + 1)
  EXPECT_POINT_NEAR(eval("bubble2", {2, 0}), 1, 0);
  EXPECT_POINT_NEAR(eval("bubble2", {2, 2}, 1, {3, 0.5, 0}), 2, 1.0 / 3);
  // wdisc: radius φ/π, angle π/(r + 1), π minus it for φ > 0
  EXPECT_POINT_NEAR(eval("wdisc", {-1, 0}), 0, 1);     // φ = π: 1·(cos π/2, sin π/2)
  EXPECT_POINT_NEAR(eval("wdisc", {0, -1}), 0, -0.5);  // φ = −π/2: −½·(cos π/2, sin π/2)
  EXPECT_POINT_NEAR(eval("wdisc", {3, 0}, 2), 0, 0);   // φ = 0
}

TEST(variations_packs3, blur3D_and_rblur_replay_their_draws) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    double u[6];
    for (double& v : u) v = rng.uniform();
    // blur3D, w = 2: ρ = 2·(u1 + u2 + u3 + u4 − 2), α = 2πu0, β = πu5: ρ·sin β·(cos α, sin α)
    const double rho = 2 * (u[1] + u[2] + u[3] + u[4] - 2), a = 2 * kPi * u[0];
    EXPECT_POINT_NEAR(eval("blur3D", {7, 7}, 2, {}, {}, seed),
                      rho * std::sin(kPi * u[5]) * std::cos(a),
                      rho * std::sin(kPi * u[5]) * std::sin(a));
    // rblur at (3, 4): ρ = 2·1·(5 − 1) = 8, p + (u0 − ½, u1 − ½)·8; within offset: p
    EXPECT_POINT_NEAR(eval("rblur", {3, 4}, 1, {}, {}, seed), 3 + (u[0] - 0.5) * 8,
                      4 + (u[1] - 0.5) * 8);
    EXPECT_POINT_NEAR(eval("rblur", {0.3, 0.4}, 2, {}, {}, seed), 0.6, 0.8);
  }
}

TEST(variations_packs3, hypertile1_and_eJulia_take_their_branches) {
  // hypertile1 p 3, q 7 at 0: w·ρ̄, |ρ| = R (hypertile2's), at a multiple of 2π/3
  const double big_r = 1 / std::sqrt(1 + 1.5 / (std::cos(2 * kPi / 7) - 0.5));
  std::set<long> turns, roots;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const Point h = eval("hypertile1", {0, 0}, 1, {}, {}, seed);
    EXPECT_NEAR(std::hypot(h.x, h.y), big_r, 1e-9);
    const double k = std::atan2(h.y, h.x) / (2 * kPi / 3);
    EXPECT_NEAR(k, std::round(k), 1e-9);
    turns.insert(std::lround(k));
    // eJulia power 2 at z = i: cosh(w/2)² = (1 + cosh w)/2, so out² = (1 + i)/2
    const Point e = eval("eJulia", {0, 1}, 1, {2}, {}, seed);
    EXPECT_NEAR(e.x * e.x - e.y * e.y, 0.5, 1e-9);
    EXPECT_NEAR(2 * e.x * e.y, 0.5, 1e-9);
    roots.insert(e.x > 0);
  }
  EXPECT_EQ(turns.size(), 3u);
  EXPECT_EQ(roots.size(), 2u);
  // power 1: cosh(acosh(z)) = z, one branch
  EXPECT_POINT_NEAR(eval("eJulia", {0.5, 0.25}, 1, {1}), 0.5, 0.25);
  EXPECT_POINT_NEAR(eval("eJulia", {-2, -0.5}, 2, {1}), -4, -1);
}

TEST(variations_packs3, smartshape_maps_circles_onto_the_polygon) {
  // power 4: the unit circle onto the square [−1, 1]², each point on its own ray
  EXPECT_POINT_NEAR(eval("smartshape", {1, 0}), 1, 0);  // a side's middle: coeff 1
  const double h = std::sqrt(0.5);
  EXPECT_POINT_NEAR(eval("smartshape", {h, h}), 1, 1);  // a corner: coeff √2
  EXPECT_POINT_NEAR(eval("smartshape", {3 / std::sqrt(10.0), 1 / std::sqrt(10.0)}), 1, 1.0 / 3);
  EXPECT_POINT_NEAR(eval("smartshape", {0.3, 0.4}, 2, {4, 0, 1, 0, 0}), 0.6, 0.8);  // circle
  // compensation: the angle π/8, half way to the corner, goes half way along the side:
  // t = ¼ → atan(2·tan(π/4)·¼)/(π/2), the angle atan ½, on the side x = 1: (1, ½)
  EXPECT_POINT_NEAR(eval("smartshape", {std::cos(kPi / 8), std::sin(kPi / 8)}, 1, {4, 0, 1, 1, 1}),
                    1, 0.5);
}

TEST(variations_packs3, circleblur_and_pow_block) {
  std::set<long> branches;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    const double u0 = rng.uniform(), u1 = rng.uniform();
    // w·√u0·(cos 2πu1, sin 2πu1)
    EXPECT_POINT_NEAR(eval("circleblur", {5, 5}, 2, {}, {}, seed),
                      2 * std::sqrt(u0) * std::cos(2 * kPi * u1),
                      2 * std::sqrt(u0) * std::sin(2 * kPi * u1));
    // 4^(3/2) = 8 at angle 0 or 3π (the two square roots, cubed)
    const Point p = eval("pow_block", {4, 0}, 1, {}, {}, seed);
    EXPECT_NEAR(std::abs(p.x), 8, 1e-9);
    EXPECT_NEAR(p.y, 0, 1e-9);
    branches.insert(std::lround(p.x));
    // i^(3/2): angle 3π/4 (+ 3π): ±(−√½, √½)
    const Point q = eval("pow_block", {0, 1}, 1, {}, {}, seed);
    EXPECT_NEAR(q.x, -q.y, 1e-9);
    EXPECT_NEAR(std::hypot(q.x, q.y), 1, 1e-9);
    // correctn 2: the radius' power 3/(2·2): |16^0.75| = 8
    const Point c = eval("pow_block", {16, 0}, 1, {3, 2, 1, 2, 1}, {}, seed);
    EXPECT_NEAR(std::hypot(c.x, c.y), 8, 1e-9);
  }
  EXPECT_EQ(branches.size(), 2u);
}

TEST(variations_packs4, y_sums_its_shapes_and_puts_the_point_at_w_T2_over_r) {
  //           hypergon  n  r_h  star  n  slope  lituus  a  super  m  n1 n2 n3
  // lituus, a = 1: T = |φ/π + 1|⁻¹; at (0, 2), φ = π/2: T = ⅔, T²/r = (4/9)/2
  EXPECT_POINT_NEAR(eval("y", {1, 0}, 1, {0, 4, 1, 0, 5, 2, 1, 1}), 1, 0);
  EXPECT_POINT_NEAR(eval("y", {0, 2}, 1, {0, 4, 1, 0, 5, 2, 1, 1}), 0, 2.0 / 9);
  // super, m = 0: T = (1 + 0)^(−1) = 1 at (3, 4): (1/5)·(0.6, 0.8)
  EXPECT_POINT_NEAR(eval("y", {3, 4}, 1, {0, 4, 1, 0, 5, 2, 0, 1, 1, 0, 1, 1, 1}), 0.12, 0.16);
  // hypergon n 4, r_h 1 at φ = π/4: a = 0, s = 1 < d² = 2: T = √2 − 1; T²/√2 on the diagonal
  const double h = (3 - 2 * std::sqrt(2.0)) / 2;
  EXPECT_POINT_NEAR(eval("y", {1, 1}, 1, {1, 4, 1}), h, h);
  // star n 4, slope π/4 at φ = π/4: b = 0: T = √(1·1)/(0 + 1) = 1: (1/√2)·(1/√2, 1/√2)
  EXPECT_POINT_NEAR(eval("y", {1, 1}, 1, {0, 4, 1, 1, 4, kPi / 4}), 0.5, 0.5);
}

TEST(variations_packs4, falloff3_blurs_by_the_distance_beyond_min_distance) {
  for (double type : {0, 1, 2})  // d = 0.5 = min_distance: dist 0, w·p
    EXPECT_POINT_NEAR(eval("falloff3", {0.3, 0.4}, 2, {type}), 0.6, 0.8);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    double u[3];
    for (double& v : u) v = rng.uniform() - 0.5;
    // centre (0, 0, 3) at (4, 0): d = 5, dist = (5 − 0.5)·0.04 = 0.18
    const double dist = 0.18;
    // Gaussian: (4, 0) + dist·u_x·cos(2π·dist·u_y)·(cos(π·dist·u_z), sin(π·dist·u_z))
    const double g = dist * u[0] * std::cos(2 * kPi * dist * u[1]);
    EXPECT_POINT_NEAR(eval("falloff3", {4, 0}, 1, {0, 0, 1, 0.5, 0, 1, 1, 0, 0, 0, 0, 3}, {}, seed),
                      4 + g * std::cos(kPi * dist * u[2]), g * std::sin(kPi * dist * u[2]));
    // radial: radius 4 + u_x·dist, angle u_y·dist
    const double r = 4 + u[0] * dist, a = u[1] * dist;
    EXPECT_POINT_NEAR(eval("falloff3", {4, 0}, 1, {1, 0, 1, 0.5, 0, 1, 1, 0, 0, 0, 0, 3}, {}, seed),
                      r * std::cos(a), r * std::sin(a));
    // logarithmic, alpha 0: (4, 0) + L(1)·S(u)·dist, L(1) = (e + 1)/4, S(u) = ln(e(|u| +
    // 1))/e·sign u; square shape: d = max(4, 0, 3) = 4, dist = 3.5·0.04
    const double e = std::numbers::e, l1 = (e + 1) / 4, d2 = 3.5 * 0.04;
    const auto s = [&](double v) { return std::log(e * (std::abs(v) + 1)) / e * (v < 0 ? -1 : 1); };
    EXPECT_POINT_NEAR(eval("falloff3", {4, 0}, 1, {2, 1, 1, 0.5, 0, 1, 1, 0, 0, 0, 0, 3}, {}, seed),
                      4 + l1 * s(u[0]) * d2, l1 * s(u[1]) * d2);
  }
}

TEST(variations_packs4, hypertile3D2_is_hypertile2_at_z0) {
  // p 4, q 5: R = 1/√(1 + 1/cos(2π/5)) (cos(2π/4) = 0); 0 ↦ R turned by a multiple of π/2
  const double big_r = 1 / std::sqrt(1 + 1 / std::cos(2 * kPi / 5));
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Point h = eval("hypertile3D2", {0, 0}, 1, {4, 5}, {}, seed);
    EXPECT_NEAR(std::hypot(h.x, h.y), big_r, 1e-9);
    const Point a = eval("hypertile3D2", {0.3, -0.2}, 0.7, {4, 5}, {}, seed);
    EXPECT_POINT_NEAR(eval("hypertile2", {0.3, -0.2}, 0.7, {4, 5}, {}, seed), a.x, a.y);
  }
}

// nBlur's point seen in the plugin's sector frame: its angle a from a sector's first corner
// (the final turn by α/2 undone: A = π/2 + α/2 − β), its radius over w, and the polygon's
// radius R(a) = cos(α/2)/cos(a − α/2) on that ray (corners at 1).
struct Sector {
  double a, r, edge;
};
Sector in_sector(Point q, double n, double w) {
  const double alpha = 2 * kPi / n;
  double a = std::fmod(kPi / 2 + alpha / 2 - std::atan2(q.y, q.x), alpha);
  if (a < 0) a += alpha;
  return {a, std::hypot(q.x, q.y) / w, std::cos(alpha / 2) / std::cos(a - alpha / 2)};
}
// The distance of a from the nearest multiple of `band` whose index has parity `parity`.
double from_band(double a, double band, int parity) {
  const double c = 2 * std::round((a / band - parity) / 2) + parity;
  return std::abs(a - c * band);
}

TEST(variations_packs5, nBlur_fills_its_polygon_and_reads_no_point) {
  //          edges stripes ratio hole circum adjust equal exact highlight
  double far = 0;
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    const Point q = eval("nBlur", {0.3, -2}, 2, {5, 0, 1, 0, 0, 0, 1, 0, 1}, {}, seed);
    EXPECT_POINT_NEAR(eval("nBlur", {7, 1}, 2, {5, 0, 1, 0, 0, 0, 1, 0, 1}, {}, seed), q.x, q.y);
    const Sector s = in_sector(q, 5, 2);
    EXPECT_LE(s.r, s.edge + 1e-12) << seed;
    far = std::max(far, s.r / s.edge);
    // adjustToLinear, 4 edges: the square [−w, w]², linear's picture of the unit square
    const Point l = eval("nBlur", {0, 0}, 0.5, {4}, {}, seed);
    EXPECT_LE(std::max(std::abs(l.x), std::abs(l.y)), 0.5 + 1e-12) << seed;
  }
  EXPECT_GT(far, 0.99);  // out to the border
  // whole-number parameters rounded as JWildfire and Ember read them: 4.6 edges are 5
  EXPECT_POINT_NEAR(eval("nBlur", {0, 0}, 1, {4.6, 0.5}), eval("nBlur", {0, 0}, 1, {5, 1}).x,
                    eval("nBlur", {0, 0}, 1, {5, 1}).y);
  EXPECT_POINT_NEAR(eval("dc_ztransl", {0.3, -2}, 2, {0.2, 0.8, 3, 0, 1}), 0.6, -4);
}

TEST(variations_packs5, nBlur_leaves_its_hole_empty) {
  // hole 0.6 of the triangle, for each way of drawing the radius (equalBlur, exactCalc) and
  // with circumCircle (the outer bound the unit disc, the hole still the triangle's)
  for (double equal : {0, 1})
    for (double exact : {0, 1})
      for (double circum : {0, 1}) {
        double beyond = 0;
        for (std::uint64_t seed = 1; seed <= 400; ++seed) {
          const Point q =
              eval("nBlur", {0, 0}, 1, {3, 0, 1, 0.6, circum, 0, equal, exact, 1}, {}, seed);
          const Sector s = in_sector(q, 3, 1);
          EXPECT_GE(s.r, 0.6 * s.edge - 1e-12) << equal << exact << circum << " " << seed;
          EXPECT_LE(s.r, (circum != 0 ? 1 : s.edge) + 1e-9) << equal << exact << circum;
          beyond = std::max(beyond, s.r - s.edge);
        }
        EXPECT_EQ(beyond > 0.05, circum != 0) << equal << exact;  // the disc beyond the sides
      }
}

TEST(variations_packs5, nBlur_stripes_leave_their_gaps_empty) {
  // triangle, 2 stripes: bands of α/4 centred at its multiples, the even ones lit, ratio 0.5
  // narrowing them to half a band (±α/16 about their centres); ratio 1.5 widening them
  const double alpha = 2 * kPi / 3, band = alpha / 4;
  // 15 stripes negative, ratio 0.45 (the pack flame's): the odd bands lit, 1.55 bands wide,
  // so nothing within 0.225 band of an even multiple
  const double band15 = alpha / 30;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    const Sector s = in_sector(eval("nBlur", {0, 0}, 1, {3, 2, 0.5, 0, 0, 0}, {}, seed), 3, 1);
    EXPECT_LE(from_band(s.a, band, 0), band / 4 + 1e-9) << seed;
    EXPECT_LE(s.r, s.edge + 1e-12);
    const Sector w = in_sector(eval("nBlur", {0, 0}, 1, {3, 2, 1.5, 0, 0, 0}, {}, seed), 3, 1);
    EXPECT_LE(from_band(w.a, band, 0), 0.75 * band + 1e-9) << seed;
    const Sector m =
        in_sector(eval("nBlur", {0, 0}, 1, {3, -15, 0.45, 0.6, 0, 0, 0, 0, 0.1}, {}, seed), 3, 1);
    EXPECT_GE(from_band(m.a, band15, 0), 0.225 * band15 - 1e-9) << seed;
    EXPECT_LE(from_band(m.a, band15, 1), 0.775 * band15 + 1e-9) << seed;
    EXPECT_GE(m.r, 0.6 * m.edge - 1e-12);
  }
}

TEST(variations_packs5, nBlur_replays_its_draws) {
  // 4 edges, adjustToLinear, equalBlur, highlightEdges 1: u0 the angle in the sector, u1 the
  // sector, u2 the radius
  const double g = 13 / std::pow(4.0, 1.3), alpha = kPi / 2;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    double u[3];
    for (double& v : u) v = rng.uniform();
    const double t = 0.5 - std::atan(g * (u[0] - 0.5)) / (2 * std::atan(g / 2));
    const double a = t * alpha, turn = std::floor(4 * u[1]) * alpha;
    const double rho = std::sqrt(u[2]) * std::cos(alpha / 2) / std::cos(a - alpha / 2);
    const double beta = kPi / 2 + alpha / 2 - turn - a, w = 3 / std::sin(kPi / 4);
    EXPECT_POINT_NEAR(eval("nBlur", {5, 5}, 3, {4}, {}, seed), w * rho * std::cos(beta),
                      w * rho * std::sin(beta));
  }
}

TEST(variations_packs5, depth_blur2_blurs_by_a_star_beyond_its_radius) {
  //                 power range blur radius x0 y0 mulx muly exp
  const std::vector<double> k{3, 0.5, 10, 1, 0, 0, 1, 1, 1};
  EXPECT_POINT_NEAR(eval("depth_blur2", {0.3, 0.4}, 2, k), 0.6, 0.8);  // within: w·p
  // the ellipse: mulx 0.1 puts (0.3, 0) at distance 3, beyond the radius
  EXPECT_NE(eval("depth_blur2", {0.3, 0}, 1, {3, 0.5, 10, 1, 0, 0, 0.1}).x, 0.3);
  const double len = std::sqrt(1.25 - std::cos(kPi / 3));  // the star's edge, tip to corner
  const double gamma = std::asin(std::sin(kPi / 3) * 0.5 / len);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    const double u0 = rng.uniform(), u1 = rng.uniform();
    // at (3, 4): distance 5, the star scaled by blur/10·(5 − 1) = 4
    const double f = 6 * u0, j = std::trunc(f), x = (f - j) * len;
    const double z = std::sqrt(1 + x * x - 2 * x * std::cos(gamma));
    const double delta = std::asin(std::sin(gamma) * x / z);
    const double theta = 2 * kPi / 3 * std::trunc(j / 2) + (std::fmod(j, 2) != 0 ? delta : -delta);
    const double s = 4 * z * std::sqrt(u1);
    const Point q = eval("depth_blur2", {3, 4}, 1, k, {}, seed);
    EXPECT_POINT_NEAR(q, 3 + s * std::sin(theta), 4 - s * std::cos(theta));
    // within the star: its tips at 4, its inner corners at 2
    EXPECT_LE(std::hypot(q.x - 3, q.y - 4), 4 + 1e-9);
  }
}

}  // namespace
}  // namespace ifsfx::flame
