// SPDX-License-Identifier: Apache-2.0
// Writing flames: read, write, read gives the same flame; an affine IFS becomes a flame whose
// xforms are its maps seen in the flame plane (y down) and whose camera frames what ifsfx frames;
// flam3-render (when installed) renders the written files, and draws the IFS's attractor where
// ifsfx draws it.
#include "flame/flame_write.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <opencv2/imgproc.hpp>

#include "flame/flame_file.h"
#include "flame/xform_eval.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/render.h"
#include "known_ifs.h"
#include "variation_check.h"

namespace ifsfx::flame {
namespace {

namespace fs = std::filesystem;

VariationTerm term(const char* name, double weight, std::vector<double> params = {}) {
  const Variation* v = find_variation(name);
  std::vector<double> p = default_parameters(*v);
  std::copy(params.begin(), params.end(), p.begin());
  return {.id = v->id, .weight = weight, .params = p};
}

// A flame using every part of the model a file can hold.
Flame full_flame() {
  Flame f;
  f.name = "all <parts> & \"quotes\",\ta line\r\nbreak";
  f.camera = {.width = 320,
              .height = 200,
              .center = {0.1, -0.7},
              .scale = 123.456,
              .zoom = 0.5,
              .rotate = -15};
  f.tone = {.brightness = 3.5,
            .gamma = 2.2,
            .gamma_threshold = 0.05,
            .vibrancy = 0.7,
            .highlight_power = 2,
            .contrast = 1.1,
            .background = {0.25, 0.5, 0.75, 0}};
  f.filtering = {.supersample = 3,
                 .filter_radius = 0.8,
                 .filter_shape = "mitchell",
                 .estimator_radius = 5,
                 .estimator_minimum = 0.5,
                 .estimator_curve = 0.3};
  f.quality = 77;
  // Files hold palettes in bytes: entries b/255 come back exactly.
  for (std::size_t k = 0; k < 256; ++k)
    f.palette.colours[k] = {k / 255.0, (255 - k) / 255.0, 51 / 255.0, k % 2 ? 1.0 : 153 / 255.0};
  f.palette.mode = PaletteMode::linear;
  f.xforms.push_back({.name = "first",
                      .pre = {0.5, -0.25, 0.125, 0.75, 1.0 / 3, -2},
                      .post = AffineMap{1, 0.1, -0.1, 1, 0.01, 0.02},
                      .weight = 0.3,
                      .colour = 0.25,
                      .colour_speed = 0.1,
                      .opacity = 0.9,
                      .chaos = {1, 2},
                      .pre_variations = {term("pre_blur", 0.05), term("julian", 0.5, {4, -1})},
                      .variations = {term("linear", 0.5), term("blob", 0.25, {1.5, 0.5, 6})},
                      .post_variations = {term("curl", 0.1, {0.2, 0.3})}});
  f.xforms.push_back({.pre = {0.6, 0, 0, 0.6, 0, 0.4},
                      .weight = 0.7,
                      .colour = 1,
                      .variations = {term("spherical", 1)}});
  f.final_xform =
      Xform{.pre = {1, 0, 0, 1, 0, 0}, .colour_speed = 0, .variations = {term("sinusoidal", 1)}};
  return f;
}

TEST(flame_write, read_write_read_gives_the_same_flame) {
  const Flame f = full_flame();
  const std::string xml = flame_xml(f);
  const std::vector<Flame> back = parse_flames(xml, "written.flame");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0], f) << xml;
  const std::vector<Flame> two{f, f};
  EXPECT_EQ(parse_flames(flames_xml(two), "two.flame").size(), 2u);
}

TEST(flame_write, every_variation_keeps_its_parameters_through_a_round_trip) {
  // each variation of the registry in one xform, in every list it may stand in, its
  // parameters moved off their defaults (by k/4 + ⅛, exact in binary)
  Flame f = full_flame();
  for (const Variation& v : variations()) {
    std::vector<double> p = default_parameters(v);
    for (std::size_t k = 0; k < p.size(); ++k) p[k] += 0.25 * static_cast<double>(k) + 0.125;
    const VariationTerm t{.id = v.id, .weight = 0.375, .params = p};
    Xform xf{.name = std::string(v.name), .pre = {1, 0, 0, 1, 0, 0}, .weight = 0.5};
    // blur's pre_ form would be written pre_blur, which files use for flam3's own pre_blur
    if (v.place == VariationPlace::pre_only || !find_variation("pre_" + xf.name))
      xf.pre_variations = {t};
    if (v.place == VariationPlace::any) {
      xf.variations = {t};
      xf.post_variations = {t};
    }
    f.xforms.push_back(xf);
  }
  const std::vector<Flame> back = parse_flames(flame_xml(f), "every.flame");
  ASSERT_EQ(back.size(), 1u);
  ASSERT_EQ(back[0].xforms.size(), f.xforms.size());
  for (std::size_t i = 0; i < f.xforms.size(); ++i)
    EXPECT_EQ(back[0].xforms[i], f.xforms[i]) << f.xforms[i].name;
  EXPECT_EQ(back[0], f);
}

TEST(flame_write, flam3_genomes_survive_a_round_trip) {
  if (std::system("command -v flam3-genome > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "flam3-genome (flam3-utils) is not installed";
  const fs::path p = fs::temp_directory_path() / "ifsfx_flame_write_genomes.flam3";
  const std::string cmd =
      "env seed=11 repeat=4 tries=1 flam3-genome > " + p.string() + " 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::vector<Flame> flames = read_flames(p.string());
  ASSERT_EQ(flames.size(), 4u);
  EXPECT_EQ(parse_flames(flames_xml(flames), "again.flame"), flames);
}

TEST(flame_write, a_flame_file_cannot_hold_a_variation_twice_in_one_list) {
  Flame f = full_flame();
  f.xforms[1].variations.push_back(term("spherical", 0.5));
  try {
    flame_xml(f);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::invalid_argument);
    EXPECT_STREQ(e.what(),
                 "xform 1: variation spherical twice in one list: a flame file holds one of each");
  }
}

TEST(flame_write, an_ifs_becomes_its_maps_in_the_flame_plane) {
  const Ifs fern = testing::barnsley_fern();
  const Flame f = flame_from_ifs(fern, {.size = {300, 400}});
  ASSERT_EQ(f.xforms.size(), 4u);
  Rng rng(1);
  const Point p{0.3, 1.7};  // the IFS plane (y up)
  for (std::size_t i = 0; i < 4; ++i) {
    const Point q = fern.maps[i](p);
    // the flame plane is the IFS plane flipped: (x, y) ↦ (x, −y)
    EXPECT_POINT_NEAR(apply_xform(f.xforms[i], {p.x, -p.y}, rng), q.x, -q.y);
    EXPECT_DOUBLE_EQ(f.xforms[i].weight, fern.probabilities[i]);
    EXPECT_DOUBLE_EQ(f.xforms[i].colour, i / 3.0);
    EXPECT_EQ(f.xforms[i].colour_speed, 0.5);
  }
  // The camera shows ifsfx's auto-framed view.
  const Viewport vp = framed_viewport(fern, {300, 400}, {});
  EXPECT_NEAR(f.camera.center.x, (vp.view.x0 + vp.view.x1) / 2, 1e-12);
  EXPECT_NEAR(f.camera.center.y, -(vp.view.y0 + vp.view.y1) / 2, 1e-12);
  EXPECT_NEAR(f.camera.scale, 300 / vp.view.width(), 1e-9);
  EXPECT_EQ(f.palette.colours[0], (Rgba{palette_ramp(0).r, palette_ramp(0).g, palette_ramp(0).b}));
}

TEST(flame_write, flam3_render_draws_a_written_ifs_where_ifsfx_draws_it) {
  if (std::system("command -v flam3-render > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "flam3-render (flam3-utils) is not installed";
  const Ifs tri = testing::sierpinski_triangle();
  const cv::Size size{96, 80};
  Flame f = flame_from_ifs(tri, {.size = size, .sampling = {.quality = 50}});
  f.filtering.filter_radius = 0;  // a point lights its own pixel only, as in ifsfx's mask
  const fs::path dir = fs::temp_directory_path();
  const fs::path in = dir / "ifsfx_flame_write_tri.flame", out = dir / "ifsfx_flame_write_tri.png";
  std::ofstream(in) << flame_xml(f);
  const std::string cmd =
      "env out=" + out.string() + " seed=3 flam3-render < " + in.string() + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const cv::Mat img = read_image(out).pixels;
  ASSERT_EQ(img.size(), size);
  cv::Mat grey;
  cv::cvtColor(img, grey, img.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  const cv::Mat theirs = grey > 0;
  const cv::Mat ours = render_attractor(tri, size, {.sampling = {.quality = 50}});
  const double inter = cv::countNonZero(theirs & ours), uni = cv::countNonZero(theirs | ours);
  // The same set on the same pixels: the triangle's boundary pixels may differ by one sample.
  EXPECT_GT(inter / uni, 0.8) << "flam3 " << cv::countNonZero(theirs) << " px, ifsfx "
                              << cv::countNonZero(ours) << " px";
}

}  // namespace
}  // namespace ifsfx::flame
