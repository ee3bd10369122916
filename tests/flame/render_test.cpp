// SPDX-License-Identifier: Apache-2.0
// The flame renderer (flame/render.h, flame/render_tone.h, flame/render_camera.h): the same
// bytes for any thread count, the display on hand-built densities, density estimation and the
// spatial filter on known inputs, the camera on one-point flames, and the orientation against
// flam3-render (skipped without it).
#include "flame/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "flame/detail/batch_variations.h"
#include "flame/detail/density_kernel.h"
#include "flame/detail/render_chaos.h"
#include "flame/flame_file.h"
#include "flame/render_camera.h"
#include "flame/render_tone.h"
#include "flame/variations.h"
#include "flame/xform_eval.h"
#include "ifs/cpu.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/rng.h"

namespace ifsfx::flame {
namespace {

namespace fs = std::filesystem;

VariationTerm term(const char* name, double weight) {
  const Variation* v = find_variation(name);
  return {v->id, weight, default_parameters(*v)};
}

// Two constant maps: every point lands on (0.5, −0.25) (palette entry 0, red) or on
// (−0.3, 0.4) (entry 255, green). No density estimation, no spatial filter.
Flame two_points() {
  Flame f;
  f.camera = {.width = 64, .height = 48, .center = {0.1, -0.05}, .scale = 40};
  f.filtering = {.supersample = 1, .filter_radius = 0, .estimator_radius = 0};
  f.tone.gamma = 1;
  f.quality = 20;
  for (int i = 0; i < 256; ++i) f.palette.colours[i] = i < 128 ? Rgba{1, 0, 0} : Rgba{0, 1, 0};
  Xform red{.pre = {0, 0, 0, 0, 0.5, -0.25}, .colour = 0, .colour_speed = 1};
  Xform green{.pre = {0, 0, 0, 0, -0.3, 0.4}, .colour = 1, .colour_speed = 1};
  red.variations = {term("linear", 1)};
  green.variations = {term("linear", 1)};
  f.xforms = {red, green};
  return f;
}

// The pixels that are not black, as (column, row).
std::vector<cv::Point> lit(const cv::Mat& bgr) {
  std::vector<cv::Point> out;
  for (int r = 0; r < bgr.rows; ++r)
    for (int c = 0; c < bgr.cols; ++c)
      if (bgr.at<cv::Vec3b>(r, c) != cv::Vec3b(0, 0, 0)) out.emplace_back(c, r);
  return out;
}

// Whether Debian's flam3-render (flam3-utils), the reference of the tests below, is here.
bool flam3_render_installed() {
  return std::system("command -v flam3-render > /dev/null 2>&1") == 0;
}

// `xml` (a <flame> element) written to TEMP/ifsfx_render_NAME.flame and rendered there by
// flam3-render with seed 1 (its picture: an empty Mat where it failed); `flame` gets the file.
cv::Mat flam3_picture(const std::string& name, const std::string& xml, fs::path& flame) {
  const fs::path dir = fs::temp_directory_path();
  flame = dir / ("ifsfx_render_" + name + ".flame");
  const fs::path out = dir / ("ifsfx_render_" + name + ".png");
  std::FILE* file = std::fopen(flame.c_str(), "w");
  if (file == nullptr) return {};
  std::fputs(xml.c_str(), file);
  std::fclose(file);
  const std::string cmd =
      "env out=" + out.string() +
      " seed=1 isaac_seed=1 format=png verbose=0 transparency=0 flam3-render < " + flame.string() +
      " > /dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0) return {};
  return read_image(out).pixels;
}

TEST(render_flame, a_point_lands_where_the_camera_formula_puts_it) {
  // x_pix = (x − cx)·ppu + W/2: (0.5 − 0.1)·40 + 32 = 48, (−0.25 + 0.05)·40 + 24 = 16.
  const cv::Mat img = render_flame(two_points(), {.seed = 3});
  ASSERT_EQ(lit(img), (std::vector<cv::Point>{{48, 16}, {16, 42}}));
  EXPECT_EQ(img.at<cv::Vec3b>(16, 48), cv::Vec3b(0, 0, 255));  // BGR: red, full density
  EXPECT_EQ(img.at<cv::Vec3b>(42, 16), cv::Vec3b(0, 255, 0));
}

TEST(render_flame, gives_bgra_and_16_bit_and_float_pictures) {
  // The red point at full density: display value 256·(α^1/α) = 256, clipped to white's 255.
  const cv::Mat f = render_flame(two_points(), {.channels = 4, .depth = CV_32F});
  ASSERT_EQ(f.type(), CV_32FC4);
  EXPECT_EQ(f.at<cv::Vec4f>(16, 48), cv::Vec4f(0, 0, 1, 1));
  EXPECT_EQ(f.at<cv::Vec4f>(0, 0), cv::Vec4f(0, 0, 0, 1));  // uncovered: the opaque background
  Flame clear = two_points();
  clear.tone.background.a = 0;  // a transparent background (JWildfire's bg_transparency)
  EXPECT_EQ(render_flame(clear, {.channels = 4, .depth = CV_32F}).at<cv::Vec4f>(0, 0),
            cv::Vec4f(0, 0, 0, 0));
  const cv::Mat w = render_flame(two_points(), {.depth = CV_16U});
  ASSERT_EQ(w.type(), CV_16UC3);
  EXPECT_EQ(w.at<cv::Vec3w>(42, 16), cv::Vec3w(0, 65535, 0));
  EXPECT_THROW(render_flame(two_points(), {.channels = 2}), Error);
}

TEST(render_flame, rotate_turns_the_plotted_points_clockwise_about_the_centre) {
  // By 90°: (dx, dy) = (0.4, −0.2) from the centre ↦ (−dy, dx) = (0.2, 0.4) → (40, 40).
  Flame f = two_points();
  f.camera.rotate = 90;
  EXPECT_EQ(lit(render_flame(f)), (std::vector<cv::Point>{{14, 8}, {40, 40}}));
  // zoom 1 doubles the scale: (0.4·80 + 32, −0.2·80 + 24) = (64, 8) is just outside; the
  // other point, (−0.4·80 + 32, 0.45·80 + 24) = (0, 60), too.
  f.camera.rotate = 0;
  f.camera.zoom = 1;
  EXPECT_TRUE(lit(render_flame(f)).empty());
}

TEST(render_flame, the_same_seed_gives_the_same_bytes_for_any_thread_count) {
  Flame f = two_points();
  f.camera = {.width = 96, .height = 80, .center = {0, 0}, .scale = 30};
  f.filtering = {.supersample = 2, .filter_radius = 0.6, .estimator_radius = 4};
  f.xforms[0].pre = {0.5, 0.1, -0.2, 0.5, 0.3, 0.1};
  f.xforms[0].variations = {term("julia", 0.6), term("spherical", 0.4)};
  f.xforms[1].pre = {0.6, 0, 0, 0.6, -0.4, 0};
  f.xforms[1].variations = {term("swirl", 1), term("blur", 0.05)};
  f.xforms[1].chaos = {2, 1};
  f.final_xform = Xform{.pre = {1, 0, 0, 1, 0, 0}, .colour = 0.5, .colour_speed = 0.2};
  f.final_xform->variations = {term("sinusoidal", 1)};
  const cv::Mat one = render_flame(f, {.seed = 9, .threads = 1});
  for (int threads : {2, 3, 5}) {
    const cv::Mat other = render_flame(f, {.seed = 9, .threads = threads});
    EXPECT_EQ(cv::norm(one, other, cv::NORM_INF), 0) << threads << " threads";
  }
  EXPECT_GT(cv::norm(one, render_flame(f, {.seed = 10, .threads = 1}), cv::NORM_L1), 0)
      << "another seed draws other points";
}

// A flame of affine xforms only (linear terms, a post map) is walked point by point without the
// term arrays (flame/render_chaos.cpp); a term of weight 0 adds nothing but sends the same
// flame down the arrays: the two walks must give the same bytes.
// flam3_picture as 8-bit BGR, as render_flame gives it (an empty Mat where flam3 failed).
cv::Mat flam3_bgr8(const std::string& name, const std::string& xml, fs::path& flame) {
  cv::Mat picture = flam3_picture(name, xml, flame);
  if (picture.empty()) return picture;
  if (picture.channels() == 4) cv::cvtColor(picture, picture, cv::COLOR_BGRA2BGR);
  cv::Mat out;
  picture.convertTo(out, CV_8U);
  return out;
}

TEST(render_flame, an_affine_only_flame_gives_the_bytes_of_the_general_walk) {
  Flame f = two_points();
  f.filtering = {.supersample = 2, .filter_radius = 0.6, .estimator_radius = 4};
  f.xforms[0].pre = {0.5, 0.1, -0.2, 0.5, 0.3, 0.1};
  f.xforms[0].variations = {term("linear", 0.7), term("linear", 0.4)};
  f.xforms[1].pre = {0.6, 0, 0, 0.6, -0.4, 0};
  f.xforms[1].post = AffineMap{0.9, 0.2, -0.1, 0.8, 0.05, 0};
  f.xforms[1].colour_speed = 0.3;
  f.quality = 200;
  Flame general = f;
  for (Xform& xf : general.xforms) xf.variations.push_back(term("spherical", 0));
  for (int threads : {1, 2}) {
    const cv::Mat fast = render_flame(f, {.seed = 4, .threads = threads});
    EXPECT_GT(cv::countNonZero(fast.reshape(1)), 100);
    EXPECT_EQ(cv::norm(fast, render_flame(general, {.seed = 4, .threads = threads}), cv::NORM_INF),
              0)
        << threads << " threads";
  }
  // Every xform one linear term and a post map: the shape the walk runs without branches.
  Flame uniform = f;
  uniform.xforms[0].variations = {term("linear", 0.9)};
  uniform.xforms[0].post = AffineMap{1, 0.1, 0, 1, 0, 0.05};
  Flame uniform_general = uniform;
  for (Xform& xf : uniform_general.xforms) xf.variations.push_back(term("spherical", 0));
  const cv::Mat flat = render_flame(uniform, {.seed = 4, .threads = 2});
  EXPECT_GT(cv::countNonZero(flat.reshape(1)), 100);
  EXPECT_EQ(cv::norm(flat, render_flame(uniform_general, {.seed = 4, .threads = 2}), cv::NORM_INF),
            0);
  // xaos, an invisible xform (opacity 0: its points are not plotted) and one that throws its
  // points past the escape bound (its walkers start again), an xform without a post map.
  Flame mixed = uniform;
  mixed.xforms[0].chaos = {0.5, 3, 1};
  mixed.xforms[1].chaos = {2, 0, 1};
  Xform hidden{.pre = {0.4, 0.2, -0.2, 0.4, 0.1, -0.3}, .colour = 0.5, .colour_speed = 0.5};
  hidden.variations = {term("linear", 1)};
  hidden.post = AffineMap{1, 0, 0, 1, 0.2, 0};
  hidden.opacity = 0;
  Xform away{.pre = {1e6, 0, 0, 1e6, 1e6, 0}, .weight = 0.02};
  away.variations = {term("linear", 1)};
  away.post = AffineMap{1e6, 0, 0, 1e6, 0, 0};
  mixed.xforms.push_back(hidden);
  mixed.xforms.push_back(away);
  Flame mixed_general = mixed;
  for (Xform& xf : mixed_general.xforms) xf.variations.push_back(term("spherical", 0));
  FlameRenderStats stats;
  const cv::Mat walked = render_flame(mixed, {.seed = 6, .threads = 2}, &stats);
  EXPECT_GT(cv::countNonZero(walked.reshape(1)), 100);
  EXPECT_GT(stats.reseeded, 100u);
  EXPECT_EQ(cv::norm(walked, render_flame(mixed_general, {.seed = 6, .threads = 2}), cv::NORM_INF),
            0);
  // Without the invisible xform the picture has more points: the opacity was obeyed.
  mixed.xforms[2].opacity = 1;
  EXPECT_GT(cv::norm(walked, render_flame(mixed, {.seed = 6, .threads = 2}), cv::NORM_L1), 0);
}

// Where every xform sets the colour coordinate to its own (colour_speed 1), each xform's hits
// add one fixed colour: the bytes of the same flame plotted hit by hit (an identity final xform
// of colour speed 0 makes the walk colour every hit from its coordinate).
TEST(render_flame, colour_speed_one_plots_each_xforms_own_colour) {
  Flame f = two_points();
  f.filtering = {.supersample = 2, .filter_radius = 0.6, .estimator_radius = 4};
  f.xforms[0].pre = {0.5, 0.1, -0.2, 0.5, 0.3, 0.1};
  f.xforms[0].colour = 0.3;
  f.xforms[1].pre = {0.6, 0, 0, 0.6, -0.4, 0};
  f.xforms[1].colour = 0.8;
  for (int i = 0; i < 256; ++i) f.palette.colours[i] = Rgba{i / 255.0, 1 - i / 255.0, 0.5};
  Flame per_hit = f;
  per_hit.final_xform = Xform{.pre = {1, 0, 0, 1, 0, 0}, .colour_speed = 0};
  per_hit.final_xform->variations = {term("linear", 1)};
  for (const PaletteMode mode : {PaletteMode::step, PaletteMode::linear}) {
    f.palette.mode = per_hit.palette.mode = mode;
    const cv::Mat fixed = render_flame(f, {.seed = 5, .threads = 2});
    EXPECT_GT(cv::countNonZero(fixed.reshape(1)), 100);
    EXPECT_EQ(cv::norm(fixed, render_flame(per_hit, {.seed = 5, .threads = 2}), cv::NORM_INF), 0);
  }
}

// linear3D is linear in the plane and walks as linear does, in double: an attractor near
// x = 10⁴, where a float's step (~10⁻³) is a twentieth of a bin, gives linear's bytes (until
// 27 Nov linear3D ran as a float batch form and moved bins).
TEST(render_flame, linear3d_walks_as_linear_in_double) {
  Flame f = two_points();
  f.camera = {.width = 64, .height = 48, .center = {10000.7, 0.6}, .scale = 40};
  f.xforms[0].pre = {0.5, 0.1, -0.1, 0.5, 5000.17, 1000.45};  // fixed: (10000.5, 0.8)
  f.xforms[1].pre = {0.5, 0, 0, 0.5, 5000.5, 0.3};            // fixed: (10001, 0.6)
  for (Xform& xf : f.xforms) xf.variations = {term("linear", 1)};
  f.quality = 50;
  Flame in_3d = f;
  for (Xform& xf : in_3d.xforms) xf.variations = {term("linear3D", 1)};
  const cv::Mat want = render_flame(f, {.seed = 3, .threads = 1});
  EXPECT_GT(cv::countNonZero(want.reshape(1)), 50);
  EXPECT_EQ(cv::norm(want, render_flame(in_3d, {.seed = 3, .threads = 1}), cv::NORM_INF), 0);
}

// A bin's 32-bit sums wrap after 2^16 hits of full colour: two constant maps, 150 000 hits
// each, still count every hit.
TEST(render_flame, a_bin_of_more_than_65536_hits_counts_every_hit) {
  const Flame f = two_points();
  const std::uint64_t points = 300000;
  const detail::ChaosResult r = detail::run_chaos_game(
      {.flame = &f, .raster = flame_raster(f.camera, 1, 0), .points = points, .threads = 2});
  double hits = 0, most = 0;
  for (std::size_t i = 3; i < r.histogram.rgba.size(); i += 4) {
    hits += r.histogram.rgba[i];
    most = std::max(most, r.histogram.rgba[i]);
  }
  EXPECT_EQ(hits, static_cast<double>(points));
  EXPECT_GT(most, 2 * 65536.0);
}

// The walk's bin numbering (flame/detail/batch_variations.h): known bins at a rotated camera's
// corners and edges, points off the raster and escaped ones, and every kernel level the scalar
// level's numbers on random points around the raster, with a count not a multiple of four.
TEST(render_flame, bin_numbers_are_the_cameras_bins_at_every_kernel_level) {
  const detail::BinGrid g{.to_bins = {2, 0.5, -0.5, 2, 10, 20}, .bins_x = 30, .bins_y = 40};
  // (bx, by) = (2x + 0.5y + 10, −0.5x + 2y + 20)
  const std::vector<double> x = {0, -5, 9.99, 0, 0, 0, 1e10, NAN, 0, -5.001, 1};
  const std::vector<double> y = {0, 0, 0, 9.99, -10, 10, 0, 0, -1e10, 0, 1};
  const std::vector<std::uint32_t> want = {20 * 30 + 10,     // the centre (10, 20)
                                           22 * 30 + 0,      // bx = 0: the first column
                                           15 * 30 + 29,     // bx = 29.98: the last
                                           39 * 30 + 14,     // by = 39.98: the last row
                                           0 * 30 + 5,       // by = 0: the first
                                           detail::kOffBin,  // by = 40: below the raster
                                           detail::kOffBin,  // |x| = 10^10: escaped
                                           detail::kOffBin,  // not a number: escaped
                                           detail::kOffBin,  // |y| = 10^10: escaped
                                           detail::kOffBin,  // bx = −0.002
                                           21 * 30 + 12};    // (12.5, 21.5)
  const std::size_t n = x.size();
  for (CpuLevel level : supported_cpu_levels()) {
    std::vector<std::uint32_t> at(n + 4, 7);
    std::vector<double> px = x, py = y;
    px.resize(n + 4, 0);
    py.resize(n + 4, 0);
    EXPECT_EQ(detail::bin_function(level)(g, n, px.data(), py.data(), at.data()), 3u)
        << to_string(level);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(at[i], want[i]) << to_string(level) << " " << i;
  }
  Rng rng(3);
  const std::size_t m = 1003;
  std::vector<double> rx(m + 4), ry(m + 4);
  for (std::size_t i = 0; i < m; ++i) {
    rx[i] = 40 * rng.uniform() - 20;
    ry[i] = 40 * rng.uniform() - 20;
  }
  rx[17] = INFINITY;
  ry[18] = -1e11;
  std::vector<std::uint32_t> ref(m + 4);
  const std::size_t gone =
      detail::bin_function(CpuLevel::scalar)(g, m, rx.data(), ry.data(), ref.data());
  EXPECT_EQ(gone, 2u);
  EXPECT_GT(std::count(ref.begin(), ref.begin() + m, detail::kOffBin), 100);
  EXPECT_LT(std::count(ref.begin(), ref.begin() + m, detail::kOffBin), 900);
  for (CpuLevel level : supported_cpu_levels()) {
    std::vector<std::uint32_t> at(m + 4);
    EXPECT_EQ(detail::bin_function(level)(g, m, rx.data(), ry.data(), at.data()), gone);
    EXPECT_TRUE(std::equal(ref.begin(), ref.begin() + m, at.begin())) << to_string(level);
  }
}

// The walk's listing of walkers by xform: each xform's walkers in ascending order at a known
// pick, and every kernel level the scalar level's list on random picks of 1 to 8 xforms and
// walker counts that are not whole vectors.
TEST(render_flame, walkers_are_listed_by_xform_in_order_at_every_kernel_level) {
  const std::vector<std::uint32_t> k = {2, 0, 2, 1, 0, 0, 2, 2, 1, 0, 2, 0, 0, 0, 0, 0};
  const std::size_t m = 11;  // the last five entries of k are padding
  for (CpuLevel level : supported_cpu_levels()) {
    std::vector<std::uint32_t> order(m + 8, 99);
    std::vector<std::size_t> first(4);
    detail::list_function(level)(k.data(), m, 3, order.data(), first.data());
    EXPECT_EQ(first, (std::vector<std::size_t>{0, 4, 6, 11})) << to_string(level);
    order.resize(m);
    EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 4, 5, 9, 3, 8, 0, 2, 6, 7, 10}))
        << to_string(level);
  }
  Rng rng(11);
  for (std::size_t steps = 1; steps <= detail::kListXforms; ++steps) {
    const std::size_t n = 256 - 3 * steps;
    std::vector<std::uint32_t> picks(n + 8, 0);
    for (std::size_t i = 0; i < n; ++i) picks[i] = rng.below(static_cast<std::uint32_t>(steps));
    std::vector<std::uint32_t> ref(n + 8);
    std::vector<std::size_t> ref_first(steps + 1);
    detail::list_function(CpuLevel::scalar)(picks.data(), n, steps, ref.data(), ref_first.data());
    EXPECT_EQ(ref_first[steps], n);
    for (std::size_t j = 0; j < steps; ++j)
      for (std::size_t i = ref_first[j]; i < ref_first[j + 1]; ++i) {
        EXPECT_EQ(picks[ref[i]], j);
        if (i > ref_first[j]) {
          EXPECT_LT(ref[i - 1], ref[i]);
        }
      }
    for (CpuLevel level : supported_cpu_levels()) {
      std::vector<std::uint32_t> order(n + 8);
      std::vector<std::size_t> first(steps + 1);
      detail::list_function(level)(picks.data(), n, steps, order.data(), first.data());
      EXPECT_EQ(first, ref_first) << to_string(level) << " " << steps;
      EXPECT_TRUE(
          std::equal(ref.begin(), ref.begin() + static_cast<std::ptrdiff_t>(n), order.begin()))
          << to_string(level) << " " << steps;
    }
  }
}

// The walk's plot kernel: a step palette's entry ⌊256·c⌋ and a linear palette's mix of two
// entries at known coordinates, a sum wrapped past 2³² reported where it happened, the walkers
// off the raster left out of the list of hits, and every kernel level the scalar level's list,
// sums and wraps on random hits.
TEST(render_flame, the_plot_adds_palette_colours_and_reports_wraps_at_every_kernel_level) {
  // 257 entries: xform 1's 256 start at the second.
  std::vector<std::uint32_t> table(4 * 257);
  for (std::uint32_t e = 0; e < 257; ++e)
    for (std::uint32_t ch = 0; ch < 4; ++ch) table[4 * e + ch] = e * 256 + ch;
  const std::uint32_t* tables[] = {table.data(), table.data() + 4};  // xform 1: entries shifted
  for (CpuLevel level : supported_cpu_levels()) {
    const detail::PlotFunction plot = detail::plot_function(level);
    std::vector<std::uint32_t> bins(4 * 3, 0);
    const std::uint32_t at[] = {0, detail::kOffBin, 1, 2, 0, 0, 0, 0};  // 4 walkers, padding
    const std::uint32_t k[] = {0, 0, 1, 0};
    // c = 0.5 → entry 128; c = 2 → clamped to entry 255; at bin 1 xform 1's entry 10 is 11.
    const double c[] = {0.5, 0.3, 10.5 / 256, 2};
    std::vector<std::uint32_t> listed(4 + 8, 99);
    ASSERT_EQ(detail::hits_function(level)(at, 4, listed.data()), 3u) << to_string(level);
    listed.resize(3);
    EXPECT_EQ(listed, (std::vector<std::uint32_t>{0, 2, 3})) << to_string(level);
    const std::uint32_t* hits = listed.data();
    unsigned wrapped = 0;
    EXPECT_EQ(plot({tables, false}, bins.data(), 0, 3, hits, at, k, c, &wrapped), 3u);
    EXPECT_EQ(bins[0], 128u * 256) << to_string(level);
    EXPECT_EQ(bins[4 + 1], 11u * 256 + 1) << to_string(level);
    EXPECT_EQ(bins[8 + 2], 255u * 256 + 2) << to_string(level);
    // Linear: c = 10.5/256 is halfway between entries 10 and 11; c = 2 the last entry.
    std::fill(bins.begin(), bins.end(), 0);
    EXPECT_EQ(plot({tables, true}, bins.data(), 0, 3, hits, at, k, c, &wrapped), 3u);
    EXPECT_EQ(bins[0], 128u * 256) << to_string(level);
    EXPECT_EQ(bins[4 + 3], 11u * 256 + 128 + 3) << to_string(level);
    EXPECT_EQ(bins[8], 255u * 256) << to_string(level);
    // Fixed colours per xform: the coordinates are not read.
    const std::uint32_t fixed[] = {1, 2, 3, 4, 10, 20, 30, 40};
    std::fill(bins.begin(), bins.end(), 0);
    EXPECT_EQ(plot({tables, true, fixed}, bins.data(), 0, 3, hits, at, k, c, &wrapped), 3u);
    EXPECT_EQ(bins, (std::vector<std::uint32_t>{1, 2, 3, 4, 10, 20, 30, 40, 1, 2, 3, 4}))
        << to_string(level);
    // Without a list, the walkers [from, n) themselves: walkers 2 and 3.
    std::fill(bins.begin(), bins.end(), 0);
    EXPECT_EQ(plot({tables, false}, bins.data(), 2, 4, nullptr, at, k, c, &wrapped), 4u);
    EXPECT_EQ(bins[0], 0u) << to_string(level);
    EXPECT_EQ(bins[4 + 1], 11u * 256 + 1) << to_string(level);
    EXPECT_EQ(bins[8 + 2], 255u * 256 + 2) << to_string(level);
    // A sum 100 below 2³² wraps at the hit that passes it: index 0, channels r and g.
    bins[0] = bins[1] = UINT32_MAX - 100;
    EXPECT_EQ(plot({tables, false}, bins.data(), 0, 3, hits, at, k, c, &wrapped), 1u);
    EXPECT_EQ(wrapped, 3u) << to_string(level);
  }
  Rng rng(8);
  const std::size_t n = 250;
  std::vector<std::uint32_t> at(n + 8), k(n);
  std::vector<double> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    at[i] = rng.below(8) == 0 ? detail::kOffBin : rng.below(16);
    k[i] = rng.below(2);
    c[i] = 1.2 * rng.uniform() - 0.1;
  }
  std::vector<std::uint32_t> hits(n + 8);
  const std::size_t listed = detail::hits_function(CpuLevel::scalar)(at.data(), n, hits.data());
  EXPECT_GT(listed, n / 2);
  EXPECT_LT(listed, n);
  for (CpuLevel level : supported_cpu_levels()) {
    std::vector<std::uint32_t> other(n + 8);
    EXPECT_EQ(detail::hits_function(level)(at.data(), n, other.data()), listed);
    EXPECT_TRUE(
        std::equal(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(listed), other.begin()))
        << to_string(level);
  }
  for (bool linear : {false, true}) {
    std::vector<std::uint32_t> ref;
    std::vector<std::size_t> ref_wraps;
    for (CpuLevel level : supported_cpu_levels()) {
      std::vector<std::uint32_t> bins(4 * 16, UINT32_MAX - 150000);  // wraps within a few hits
      std::vector<std::size_t> wraps;
      for (std::size_t j = 0; j < listed;) {
        unsigned wrapped = 0;
        j = detail::plot_function(level)({tables, linear}, bins.data(), j, listed, hits.data(),
                                         at.data(), k.data(), c.data(), &wrapped);
        if (wrapped != 0) wraps.push_back(j * 16 + wrapped);
      }
      if (ref.empty()) {
        ref = bins;
        ref_wraps = wraps;
        EXPECT_GE(wraps.size(), 10u);
      }
      EXPECT_EQ(bins, ref) << to_string(level) << (linear ? " linear" : " step");
      EXPECT_EQ(wraps, ref_wraps) << to_string(level) << (linear ? " linear" : " step");
    }
  }
}

TEST(render_tone, the_display_scales_colour_by_the_gamma_of_the_density) {
  ToneMapping tone;
  tone.gamma = 2;
  tone.gamma_threshold = 0;
  // α = 0.25: α^(1/2) = 0.5, ls = 256·0.5/0.25 = 512.
  const double px[4] = {0.25, 0.125, 0, 0.25};
  DisplayPixel p = display_pixel(px, tone);
  EXPECT_DOUBLE_EQ(p.r, 128);
  EXPECT_DOUBLE_EQ(p.g, 64);
  EXPECT_DOUBLE_EQ(p.alpha, 0.5);
  // No vibrancy: each channel's own gamma, 256·√0.125.
  tone.vibrancy = 0;
  p = display_pixel(px, tone);
  EXPECT_DOUBLE_EQ(p.r, 128);
  EXPECT_DOUBLE_EQ(p.g, 256 * std::sqrt(0.125));
}

TEST(render_tone, a_picture_with_alpha_has_straight_colour_over_the_backgrounds_alpha) {
  // Density 1/4 of pure red at half strength, gamma 2: alpha √(1/4) = 1/2, display red
  // 256·(1/2)/(1/4)·(1/8) = 64 on the 0…255 scale, premultiplied by the alpha.
  FlameHistogram h(1, 1);
  h.at(0, 0)[0] = 0.125;
  h.at(0, 0)[3] = 0.25;
  ToneMapping tone{.gamma = 2};
  tone.background = {0, 0, 1, 0};  // blue, transparent (JWildfire's bg_transparency)
  EXPECT_EQ(display(h, tone, 3, CV_32F, 1).at<cv::Vec3f>(0, 0),
            cv::Vec3f(255.0f / 2 / 255, 0, 64.0f / 255));  // opaque: half the blue behind
  EXPECT_EQ(display(h, tone, 4, CV_32F, 1).at<cv::Vec4f>(0, 0),
            cv::Vec4f(0, 0, 128.0f / 255, 0.5f));  // straight red 64 / (1/2), alpha 1/2
  tone.background.a = 1;                           // an opaque background: the 3-channel colour
  EXPECT_EQ(display(h, tone, 4, CV_32F, 1).at<cv::Vec4f>(0, 0),
            cv::Vec4f(255.0f / 2 / 255, 0, 64.0f / 255, 1));
}

TEST(render_tone, below_gamma_threshold_the_curve_blends_into_a_line) {
  ToneMapping tone;
  tone.gamma = 2;
  tone.gamma_threshold = 0.01;
  // α = 0.005, half the threshold: ½·α·√0.01/0.01 + ½·√α.
  const double px[4] = {0.005, 0.005, 0.005, 0.005};
  const double expected = 0.5 * 0.005 * 0.1 / 0.01 + 0.5 * std::sqrt(0.005);
  EXPECT_DOUBLE_EQ(display_pixel(px, tone).alpha, expected);
  EXPECT_NEAR(display_pixel(px, tone).r, 256 * expected, 1e-12);
}

TEST(render_tone, highlight_power_keeps_the_hue_of_a_clipped_colour) {
  ToneMapping tone;
  tone.gamma = 1;
  const double px[4] = {2, 1, 0, 1};  // ls = 256: (512, 256, 0) before clipping
  tone.highlight_power = -1;
  DisplayPixel p = display_pixel(px, tone);
  EXPECT_DOUBLE_EQ(p.r, 512);
  EXPECT_DOUBLE_EQ(p.g, 256);
  tone.highlight_power = 0;  // scaled to a largest channel of 255, saturation kept
  p = display_pixel(px, tone);
  EXPECT_DOUBLE_EQ(p.r, 255);
  EXPECT_DOUBLE_EQ(p.g, 127.5);
  EXPECT_DOUBLE_EQ(p.b, 0);
  tone.highlight_power = 1000;  // (127.5/256)^1000: no saturation left, white
  p = display_pixel(px, tone);
  EXPECT_NEAR(p.b, 255, 1e-9);
}

TEST(render_tone, log_scale_follows_brightness_area_and_quality) {
  Flame f;
  f.camera = {.width = 100, .height = 100, .scale = 10};  // area 100 units²
  const LogScale s = log_scale(f, 1, 10);
  EXPECT_DOUBLE_EQ(s.k1, 4 * 268.0 / 256);
  EXPECT_DOUBLE_EQ(s.k2, 1.0 / (100 * 10));
  EXPECT_DOUBLE_EQ(s(1000), s.k1 * std::log(2.0) / 1000);
  EXPECT_DOUBLE_EQ(log_scale(f, 2, 10).k2, 4.0 / 1000);  // ss² bins per pixel
}

TEST(render_tone, density_estimation_spreads_a_lone_hit_over_its_disc) {
  FlameHistogram h(9, 9);
  h.at(4, 4)[3] = 1;
  h.at(4, 4)[0] = 1;
  const LogScale scale{1, 1};
  const Filtering f{.estimator_radius = 2, .estimator_minimum = 0, .estimator_curve = 0.4};
  const FlameHistogram out = density_estimate(h, f, 1, scale, 1);
  // One hit: radius 1.1 · 2 / 1^0.4, held to estimator_radius, 2: offsets with d² < 4 (d² = 0,
  // four of 1, four of 2), weights e^(−4.5·d²/4), normalised.
  const auto w = [](double d2) { return std::exp(-4.5 * d2 / 4); };
  const double sum = 1 + 4 * (w(1) + w(2));
  const double ls = std::log(2.0);
  EXPECT_DOUBLE_EQ(out.at(4, 4)[3], ls / sum);
  EXPECT_DOUBLE_EQ(out.at(4, 5)[3], ls * w(1) / sum);
  EXPECT_DOUBLE_EQ(out.at(5, 5)[0], ls * w(2) / sum);
  EXPECT_EQ(out.at(4, 6)[3], 0);
  // A dense bin (10⁶ hits: radius 2/10^2.4 < 1) keeps its log density to itself.
  h.at(4, 4)[3] = 1e6;
  const FlameHistogram dense = density_estimate(h, f, 1, scale, 1);
  EXPECT_DOUBLE_EQ(dense.at(4, 4)[3], std::log1p(1e6));
  EXPECT_EQ(dense.at(4, 5)[3], 0);
}

// Without reach (radius · ss below one bin) a histogram given up is scaled in place, to the
// bits of the spreading path: each bin × ls(a), 0 where a is 0; with reach both are one path.
TEST(render_tone, density_estimation_in_place_gives_the_spreading_paths_bits) {
  FlameHistogram h(7, 5);
  Rng rng(2);
  for (std::size_t i = 0; i < h.rgba.size(); i += 4) {
    if (rng.below(3) == 0) continue;  // an empty bin
    h.rgba[i + 3] = 1 + rng.below(1000);
    for (std::size_t k = 0; k < 3; ++k) h.rgba[i + k] = h.rgba[i + 3] * rng.uniform();
  }
  const LogScale scale{1.3, 0.02};
  for (const double radius : {0.0, 0.4, 1.5})
    for (const int ss : {1, 2}) {
      const Filtering f{
          .estimator_radius = radius, .estimator_minimum = 0.2, .estimator_curve = 0.4};
      const FlameHistogram spread = density_estimate(h, f, ss, scale, 1);
      FlameHistogram copy = h;
      const FlameHistogram in_place = density_estimate(std::move(copy), f, ss, scale, 2);
      EXPECT_EQ(in_place.rgba, spread.rgba) << radius << " " << ss;
    }
  FlameHistogram one(2, 1);
  one.at(0, 1)[3] = 10;
  one.at(0, 1)[1] = 5;
  const FlameHistogram out = density_estimate(std::move(one), {.estimator_radius = 0}, 1, scale, 1);
  EXPECT_EQ(out.at(0, 1)[1], 5 * scale(10));
  EXPECT_EQ(out.at(0, 0)[3], 0);
}

// Density estimation spreads bands of 64 source rows, each into sums of its own added in band
// order (render_tone.cpp; since 27 Nov the first band to reach a row spreads into the picture's
// row, the later ones into buffers). The reference: the bands spread one at a time (the other
// bands' bins emptied; supersample 1, so a bin's radius is its own hits) and the pictures added
// in band order, from 0. Bit for bit, at a reach of 9 (two bands meet in a row), 40 and 64 (three),
// for 1, 2 and 3 threads.
TEST(render_tone, density_estimation_adds_the_bands_sums_in_band_order) {
  FlameHistogram h(9, 150);
  Rng rng(5);
  for (int r = 0; r < h.height; ++r) {
    // Sparse bins (1 or 2 hits: a radius of 40 reaches 40 or 33 rows) at the top, middle and
    // bottom of each band, so that at reach 40 the sums of three bands meet in a row with
    // like magnitudes.
    if (r % 64 > 5 && (r % 64 < 30 || r % 64 > 35) && r % 64 < 58) continue;
    for (int c = 0; c < h.width; ++c) {
      if (rng.below(3) != 0) continue;
      double* bin = h.at(r, c);
      bin[3] = 1 + rng.below(2);
      for (int k = 0; k < 3; ++k) bin[k] = bin[3] * rng.uniform();
    }
  }
  const LogScale scale{1.3, 0.02};
  for (const double radius : {9.0, 40.0, 64.0}) {
    const Filtering f{.estimator_radius = radius, .estimator_minimum = 0, .estimator_curve = 0.4};
    std::vector<FlameHistogram> parts;
    for (int band = 0; band * 64 < h.height; ++band) {
      FlameHistogram one(h.width, h.height);
      for (int r = band * 64; r < std::min(h.height, band * 64 + 64); ++r)
        std::copy(h.at(r, 0), h.at(r, 0) + 4 * h.width, one.at(r, 0));
      parts.push_back(density_estimate(one, f, 1, scale, 1));
    }
    FlameHistogram expected(h.width, h.height), reversed(h.width, h.height);
    for (std::size_t i = 0; i < expected.rgba.size(); ++i)
      for (std::size_t b = 0; b < parts.size(); ++b) {
        expected.rgba[i] += parts[b].rgba[i];
        reversed.rgba[i] += parts[parts.size() - 1 - b].rgba[i];
      }
    // Where three bands meet the order shows in the last bits (else this could not fail; two
    // sums add the same either way).
    if (radius > 9) {
      EXPECT_NE(reversed.rgba, expected.rgba);
    }
    for (const int threads : {1, 2, 3})
      EXPECT_EQ(density_estimate(h, f, 1, scale, threads).rgba, expected.rgba)
          << radius << " " << threads;
  }
}

// A bin's kernel follows its own density, though the renderer keeps the last few densities'
// kernels (and hits' log scales) in a table: 120 lone bins, 8 bins apart, of hits that repeat
// and that differ (whole and fractional, more than the table holds), each spread with the
// centre weight of its own radius, 1.1·3/a^0.4 held to [1, 3] and quantised to 1/16 bin.
TEST(render_tone, density_estimation_picks_each_bins_kernel_by_its_own_density) {
  constexpr int kBins = 120;
  FlameHistogram h(8 * kBins, 7);
  const auto hits = [](int i) { return i % 3 == 0 ? 1.0 + i % 7 : 0.5 + 0.75 * i; };
  for (int i = 0; i < kBins; ++i) {
    h.at(3, 8 * i + 3)[3] = hits(i);
    h.at(3, 8 * i + 3)[1] = 0.5 * hits(i);
  }
  const LogScale scale{1, 0.3};
  const Filtering f{.estimator_radius = 3, .estimator_minimum = 1, .estimator_curve = 0.4};
  const FlameHistogram out = density_estimate(h, f, 1, scale, 2);
  for (int i = 0; i < kBins; ++i) {
    const double a = hits(i);
    const double radius = std::lround(std::clamp(1.1 * 3 / std::pow(a, 0.4), 1.0, 3.0) * 16) / 16.0;
    double sum = 0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx) {
        const double d2 = (dx * dx + dy * dy) / (radius * radius);
        if (d2 < 1) sum += std::exp(-4.5 * d2);
      }
    EXPECT_DOUBLE_EQ(out.at(3, 8 * i + 3)[3], scale(a) * a / sum) << i << " " << a;
    EXPECT_DOUBLE_EQ(out.at(3, 8 * i + 3)[1], scale(a) * 0.5 * a / sum) << i << " " << a;
  }
}

// Density estimation's row of a disc, o[4i + k] += w[i]·v[k]: at every kernel level the CPU
// runs, the scalar level's bits (a product then a sum, no FMA), for rows of 0 to 40 taps at
// any offset, and the plain formula's.
TEST(render_tone, the_spread_row_gives_the_scalar_bits_at_every_kernel_level) {
  Rng rng(11);
  for (int n = 0; n <= 40; ++n) {
    std::vector<double> w(static_cast<std::size_t>(n) + 1), o(4 * w.size() + 4);
    for (double& x : w) x = rng.uniform();
    for (double& x : o) x = rng.uniform() * 100;
    const double v[4] = {rng.uniform(), rng.uniform() * 1e-3, rng.uniform() * 7, 1 / 3.0};
    const int at = static_cast<int>(rng.below(2));  // row start: 4·at doubles in
    std::vector<double> expected = o;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 4; ++k) {
        const double p = w[static_cast<std::size_t>(i)] * v[k];  // no FMA: a product, then a sum
        expected[static_cast<std::size_t>(4 * (at + i) + k)] += p;
      }
    for (const CpuLevel level : supported_cpu_levels()) {
      std::vector<double> got = o;
      detail::spread_row_function(level)(got.data() + 4 * at, w.data(), n, v);
      EXPECT_EQ(got, expected) << to_string(level) << " " << n;
    }
  }
}

TEST(render_tone, the_gaussian_filter_of_half_a_pixel_has_three_taps) {
  // span 2·1.5·0.5 = 1.5 → 3 taps (odd, as ss), at x = −2, 0, 2: e^−8, 1, e^−8.
  const SpatialKernel k = spatial_kernel("gaussian", 0.5, 1);
  ASSERT_EQ(k.width, 3);
  EXPECT_EQ(k.gutter, 1);
  EXPECT_DOUBLE_EQ(k.taps[1], 1 / (1 + 2 * std::exp(-8.0)));
  EXPECT_THROW(spatial_kernel("sharp", 0.5, 1), Error);
}

TEST(render_flame, draws_an_asymmetric_flame_as_flam3_render_does) {
  if (!flam3_render_installed()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  // An L of constant maps (colour speed 1: each point has its map's colour exactly, so the
  // pictures agree to the byte) plus a rotation and an off-centre camera: a mirror, a transpose or
  // a turn the wrong way moves the lit pixels.
  const std::string xml = R"(<flame name="L" size="64 48" center="0.1 -0.05" scale="40"
    rotate="30" quality="10" filter="0" oversample="1" estimator_radius="0" gamma="1">
  <xform weight="1" color="0" color_speed="1" linear="1" coefs="0 0 0 0 0.5 -0.25"/>
  <xform weight="1" color="0.5" color_speed="1" linear="1" coefs="0 0 0 0 -0.3 0.4"/>
  <xform weight="1" color="1" color_speed="1" linear="1" coefs="0 0 0 0 -0.3 -0.2"/>
  <color index="0" rgb="255 0 0"/>)";
  std::string text = xml;
  for (int i = 1; i < 256; ++i)
    text += "<color index=\"" + std::to_string(i) + "\" rgb=\"" +
            (i < 192 ? "0 255 0" : "0 0 255") + "\"/>";
  text += "</flame>";
  fs::path in;
  const cv::Mat theirs8 = flam3_bgr8("L", text, in);
  ASSERT_FALSE(theirs8.empty());
  const cv::Mat ours = render_flame(read_flame(in.string()));
  EXPECT_EQ(lit(ours), lit(theirs8));
  EXPECT_EQ(cv::norm(ours, theirs8, cv::NORM_INF), 0);
}

TEST(render_flame, an_xform_without_variations_is_flam3_renders_constant_map) {
  if (!flam3_render_installed()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  // The second xform has no variation at all: flam3 sums none to (0, 0), which its post map
  // moves to (−0.3, 0.4) whatever its pre-affine map (one that would draw elsewhere).
  const std::string xml = R"(<flame name="empty" size="64 48" center="0.1 -0.05" scale="40"
    quality="10" filter="0" oversample="1" estimator_radius="0" gamma="1">
  <xform weight="1" color="0" color_speed="1" linear="1" coefs="0 0 0 0 0.5 -0.25"/>
  <xform weight="1" color="1" color_speed="1" coefs="0.5 0 0 0.5 0.2 0.3"
    post="1 0 0 1 -0.3 0.4"/>
  <color index="0" rgb="255 0 0"/>)";
  std::string text = xml;
  for (int i = 1; i < 256; ++i)
    text += "<color index=\"" + std::to_string(i) + "\" rgb=\"0 255 0\"/>";
  text += "</flame>";
  fs::path in;
  const cv::Mat theirs8 = flam3_bgr8("empty", text, in);
  ASSERT_FALSE(theirs8.empty());
  const Flame flame = read_flame(in.string());
  ASSERT_TRUE(flame.xforms[1].variations.empty());
  const cv::Mat ours = render_flame(flame);
  EXPECT_EQ(lit(ours).size(), 2u);
  EXPECT_EQ(lit(ours), lit(theirs8));
  EXPECT_EQ(cv::norm(ours, theirs8, cv::NORM_INF), 0);
}

TEST(render_flame, post_terms_come_before_the_post_map_as_in_apply_xform) {
  // One xform: pre_ term, sum, post_ term and a post map; its final image of a point is
  // apply_xform's (post_spherical then the post map). A lone constant start: the pre-affine map
  // sends every point to (0.4, 0.2); pre_spherical (2, 1); 0.5·linear (1, 0.5); post_spherical
  // (0.8, 0.4); the post map + (−0.5, 0.1) → (0.3, 0.5). The other order: the post map first
  // (0.5, 0.6), then spherical (0.82, 0.98).
  Flame f = two_points();
  Xform& xf = f.xforms[1];
  xf.pre = {0, 0, 0, 0, 0.4, 0.2};
  xf.pre_variations = {term("spherical", 1)};
  xf.variations = {term("linear", 0.5)};
  xf.post_variations = {term("spherical", 1)};
  xf.post = AffineMap{1, 0, 0, 1, -0.5, 0.1};
  Rng rng(1);
  const Point p = apply_xform(xf, {0, 0}, rng);
  EXPECT_NEAR(p.x, 0.3, 1e-9);  // spherical's 1/(r² + 1e-10)
  EXPECT_NEAR(p.y, 0.5, 1e-9);
  f.xforms.erase(f.xforms.begin());
  const std::vector<cv::Point> at = lit(render_flame(f));
  // The camera formula (a_point_lands_where_the_camera_formula_puts_it): (0.3 − 0.1)·40 + 32 =
  // 40, (0.5 + 0.05)·40 + 24 = 46; the other order's (0.82, 0.98) is off the picture.
  EXPECT_EQ(at, (std::vector<cv::Point>{{40, 46}}));
}

// A flame whose every point lands on one bin (the constant map to (0.001, 0.001), a white
// palette, gamma 1: density estimation alone spreads it, the picture linear in the spread
// values), `size` pixels square, `flame_attributes` the rest of the <flame> element's. Its
// pictures by flam3-render (`theirs`) and ifsfx (`ours`), grey; false where flam3 failed.
bool lone_bin_pictures(const std::string& name, int size, const std::string& flame_attributes,
                       cv::Mat& theirs, cv::Mat& ours) {
  std::string text = "<flame name=\"" + name + "\" size=\"" + std::to_string(size) + " " +
                     std::to_string(size) + "\" center=\"0 0\" scale=\"10\" filter=\"0.2\" " +
                     "estimator_minimum=\"0\" estimator_curve=\"0.4\" gamma=\"1\" " +
                     "gamma_threshold=\"0\" vibrancy=\"1\" " + flame_attributes + ">" +
                     R"(<xform weight="1" color="0" linear="1" coefs="0 0 0 0 0.001 0.001"/>)";
  for (int i = 0; i < 256; ++i)
    text += "<color index=\"" + std::to_string(i) + "\" rgb=\"255 255 255\"/>";
  text += "</flame>";
  fs::path in;
  const cv::Mat picture = flam3_picture(name, text, in);
  if (picture.empty()) return false;
  cv::cvtColor(picture, theirs, cv::COLOR_BGRA2GRAY);
  cv::cvtColor(render_flame(read_flame(in.string())), ours, cv::COLOR_BGR2GRAY);
  return theirs.size() == ours.size();
}

TEST(render_flame, spreads_a_lone_bin_as_flam3_render_does) {
  if (!flam3_render_installed()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  // 22 hits, radius about 1.1 · 16 / 22^0.4 = 5.1 bins. The profile across the bin and along
  // its diagonal is flam3-render's to 2 levels of 255; Epanechnikov's kernel gave 14 13 11 8 3
  // where flam3 gives 26 22 13 5 1.
  cv::Mat theirs, ours;
  ASSERT_TRUE(lone_bin_pictures("dot", 33,
                                R"(quality="0.02" supersample="1" estimator_radius="16" )"
                                R"(brightness="0.4")",
                                theirs, ours));
  ASSERT_GT(theirs.at<std::uint8_t>(16, 16), 20);
  for (int d = 0; d <= 6; ++d) {
    EXPECT_NEAR(ours.at<std::uint8_t>(16, 16 + d), theirs.at<std::uint8_t>(16, 16 + d), 2) << d;
    EXPECT_NEAR(ours.at<std::uint8_t>(16 + d, 16 + d), theirs.at<std::uint8_t>(16 + d, 16 + d), 2)
        << d;
  }
}

TEST(render_flame, spreads_a_lone_supersampled_bin_as_flam3_render_does) {
  if (!flam3_render_installed()) GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  // As above at supersample 2 and 100 hits, where flam3's spread is narrower than at
  // supersample 1 (the radius's factor 1.05, not 1.1: render_tone.cpp): the profile's width
  // 3σ is flam3's to 2 % (1.1 made it 4 % wider), its brightness to 2 levels.
  cv::Mat theirs, ours;
  ASSERT_TRUE(lone_bin_pictures("dot2", 65,
                                R"(quality="0.023669" supersample="2" estimator_radius="9" )"
                                R"(brightness="1")",
                                theirs, ours));
  // 3σ of the picture as a distribution of brightness about its centroid, per axis.
  const auto width = [](const cv::Mat& g) {
    const cv::Moments m = cv::moments(g);
    return 3 * std::sqrt((m.mu20 + m.mu02) / (2 * m.m00));
  };
  ASSERT_GT(theirs.at<std::uint8_t>(32, 32), 60);
  EXPECT_NEAR(width(ours) / width(theirs), 1.0, 0.02) << width(ours) << " " << width(theirs);
  for (int d = 0; d <= 6; ++d)
    EXPECT_NEAR(ours.at<std::uint8_t>(32, 32 + d), theirs.at<std::uint8_t>(32, 32 + d), 2) << d;
}

}  // namespace
}  // namespace ifsfx::flame
