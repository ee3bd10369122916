// SPDX-License-Identifier: Apache-2.0
// Reading flame XML: flames written here by hand in each program's dialect, flam3's own
// test.flam3 and flam3-genome's random genomes when flam3-utils is installed, and one-line
// errors that name the file, the flame and the attribute.
#include "flame/flame_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "flame/variations.h"
#include "ifs/error.h"
#include "variation_check.h"

namespace ifsfx::flame {
namespace {

namespace fs = std::filesystem;

std::string grey_palette() {
  std::string hex;
  for (int i = 0; i < 256; ++i) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02X%02X%02X", i, i, 255 - i);
    hex += buf;
    if (i % 8 == 7) hex += "\n";
  }
  return "<palette count=\"256\" format=\"RGB\">\n" + hex + "</palette>";
}

// A flame in the dialect of flam3 3.1 (flam3-genome's attributes).
std::string flam3_flame(const std::string& name = "one", const std::string& xform_extra = "") {
  return "<flame version=\"FLAM3-LNX-3.1.1\" name=\"" + name +
         "\" size=\"320 240\" center=\"0.5 -0.25\" scale=\"80\" zoom=\"1\" rotate=\"30\" "
         "supersample=\"2\" filter=\"0.75\" filter_shape=\"hermite\" quality=\"20\" "
         "background=\"0.1 0.2 0.3\" brightness=\"3\" gamma=\"2.5\" highlight_power=\"1\" "
         "vibrancy=\"0.5\" estimator_radius=\"7\" estimator_minimum=\"1\" estimator_curve=\"0.6\" "
         "gamma_threshold=\"0.02\" palette_mode=\"linear\">\n"
         "<xform weight=\"0.25\" color=\"0.5\" color_speed=\"0.3\" opacity=\"0.8\" "
         "chaos=\"1 0\" julian=\"0.7\" julian_power=\"3\" spherical=\"0.3\" " +
         xform_extra +
         " coefs=\"1 2 3 4 5 6\" post=\"0.5 0 0 0.5 0 1\"/>\n"
         "<xform weight=\"0.75\" color=\"1\" symmetry=\"0.5\" linear=\"1\" "
         "coefs=\"0.5 0 0 0.5 0 0\"/>\n"
         "<finalxform color=\"0.2\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>\n" +
         grey_palette() + "\n</flame>\n";
}

Error parse_error(const std::string& xml) {
  try {
    parse_flames(xml, "t.flame");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return Error(ErrorKind::io, "");
}

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p =
      fs::temp_directory_path() / ("ifsfx_flame_test_" + std::to_string(getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p;
}

TEST(flame_file, reads_every_attribute_of_a_flam3_flame) {
  const std::vector<Flame> flames = parse_flames(flam3_flame(), "t.flame");
  ASSERT_EQ(flames.size(), 1u);
  const Flame& f = flames[0];
  EXPECT_EQ(f.name, "one");
  EXPECT_EQ(f.camera.width, 320);
  EXPECT_EQ(f.camera.height, 240);
  EXPECT_EQ(f.camera.center, (Point{0.5, -0.25}));
  EXPECT_EQ(f.camera.scale, 80);
  EXPECT_EQ(f.camera.zoom, 1);
  EXPECT_EQ(f.camera.rotate, 30);
  EXPECT_EQ(f.filtering.supersample, 2);
  EXPECT_EQ(f.filtering.filter_radius, 0.75);
  EXPECT_EQ(f.filtering.filter_shape, "hermite");
  EXPECT_EQ(f.filtering.estimator_radius, 7);
  EXPECT_EQ(f.filtering.estimator_minimum, 1);
  EXPECT_EQ(f.filtering.estimator_curve, 0.6);
  EXPECT_EQ(f.quality, 20);
  EXPECT_EQ(f.tone.background, (Rgba{0.1, 0.2, 0.3, 1}));  // RGB only: opaque, as flam3
  EXPECT_EQ(f.tone.brightness, 3);
  EXPECT_EQ(f.tone.gamma, 2.5);
  EXPECT_EQ(f.tone.highlight_power, 1);
  EXPECT_EQ(f.tone.vibrancy, 0.5);
  EXPECT_EQ(f.tone.gamma_threshold, 0.02);
  EXPECT_EQ(f.palette.mode, PaletteMode::linear);
  EXPECT_EQ(f.palette.source, PaletteSource::inline_colours);
  EXPECT_EQ(f.palette.colours[255], (Rgba{1, 1, 0, 1}));
  EXPECT_EQ(f.palette.colours[0], (Rgba{0, 0, 1, 1}));
}

TEST(flame_file, reads_xforms_in_ifsfx_affine_order_with_their_terms) {
  const Flame f = parse_flames(flam3_flame(), "t.flame")[0];
  ASSERT_EQ(f.xforms.size(), 2u);
  const Xform& x = f.xforms[0];
  // coefs="1 2 3 4 5 6": x' = 1x + 3y + 5, y' = 2x + 4y + 6
  EXPECT_EQ(x.pre, (AffineMap{1, 3, 2, 4, 5, 6}));
  EXPECT_EQ(x.post, (AffineMap{0.5, 0, 0, 0.5, 0, 1}));
  EXPECT_EQ(x.weight, 0.25);
  EXPECT_EQ(x.colour, 0.5);
  EXPECT_EQ(x.colour_speed, 0.3);
  EXPECT_EQ(x.opacity, 0.8);
  EXPECT_EQ(x.chaos, (std::vector<double>{1, 0}));
  ASSERT_EQ(x.variations.size(), 2u);
  EXPECT_EQ(variation(x.variations[0].id).name, "julian");
  EXPECT_EQ(x.variations[0].weight, 0.7);
  EXPECT_EQ(x.variations[0].params, (std::vector<double>{3, 1}));  // dist: its default
  EXPECT_EQ(variation(x.variations[1].id).name, "spherical");
  // symmetry σ = 0.5 is colour speed (1 − σ)/2
  EXPECT_EQ(f.xforms[1].colour_speed, 0.25);
  EXPECT_FALSE(f.xforms[1].post.has_value());
  ASSERT_TRUE(f.final_xform.has_value());
  EXPECT_EQ(f.final_xform->colour, 0.2);
  EXPECT_EQ(f.final_xform->colour_speed, 0);  // a final xform keeps the colour unless told
}

TEST(flame_file, pre_and_post_terms_take_their_prefixed_parameters) {
  const Flame f = parse_flames(flam3_flame("p",
                                           "pre_blur=\"0.1\" pre_julian=\"0.5\" "
                                           "pre_julian_power=\"5\" post_curl=\"0.2\" "
                                           "post_curl_c1=\"0.3\" post_curl_c2=\"0.4\""),
                               "t.flame")[0];
  const Xform& x = f.xforms[0];
  ASSERT_EQ(x.pre_variations.size(), 2u);
  EXPECT_EQ(variation(x.pre_variations[0].id).name, "pre_blur");
  EXPECT_EQ(variation(x.pre_variations[1].id).name, "julian");
  EXPECT_EQ(x.pre_variations[1].params, (std::vector<double>{5, 1}));
  ASSERT_EQ(x.post_variations.size(), 1u);
  EXPECT_EQ(variation(x.post_variations[0].id).name, "curl");
  EXPECT_EQ(x.post_variations[0].weight, 0.2);
  EXPECT_EQ(x.post_variations[0].params, (std::vector<double>{0.3, 0.4}));
}

TEST(flame_file, jwildfires_motion_curves_are_read_when_off_and_refused_when_on) {
  // JWildfire writes a curve over an animation's frames for the xform's values, each term's
  // amount and each parameter: off, it changes nothing in a still.
  const std::string curves =
      "julian_fx_priority=\"0\" julian_power_enabled=\"false\" julian_power_view_xmin=\"0\" "
      "julian_power_interpolation=\"SPLINE\" julian_power_point_count=\"1\" "
      "julian_power_x0=\"1\" julian_power_y0=\"2.0\" julian_amountCurve_enabled=\"false\" "
      "weightCurve_enabled=\"false\" weightCurve_locked=\"false\" weightCurve_x0=\"1\" "
      "xyCoeff00Curve_enabled=\"false\" xyCoeff00Curve_y0=\"1.0\"";
  const Flame f = parse_flames(flam3_flame("m", curves), "t.flame")[0];
  EXPECT_EQ(f.xforms[0].variations[0].params, (std::vector<double>{3, 1}));
  std::string on = curves;
  const std::string off = "julian_power_enabled=\"false";
  on.replace(on.find(off), off.size(), "julian_power_enabled=\"true");
  EXPECT_STREQ(parse_error(flam3_flame("m", on)).what(),
               "t.flame: flame \"m\": xform 0: julian_power_enabled: a JWildfire motion curve "
               "animates this value over frames; ifsfx reads stills of flames without enabled "
               "curves (got \"true\")");
  // A curve's attributes of a value the xform does not have are still unknown.
  EXPECT_STREQ(parse_error(flam3_flame("m", "swirl_power_enabled=\"false\"")).what(),
               "t.flame: flame \"m\": xform 0: unknown variation \"swirl_power_enabled\"");
}

TEST(flame_file, jwildfires_camera_zoom_scales_and_its_3d_affine_maps_must_be_the_identity) {
  std::string zoomed = flam3_flame("z");
  zoomed.replace(zoomed.find("scale=\"80\""), 10, "scale=\"80\" cam_zoom=\"2.5\"");
  EXPECT_EQ(parse_flames(zoomed, "t.flame")[0].camera.scale, 200);
  const Flame flat = parse_flames(
      flam3_flame("y", "yzCoefs=\"1.0 0.0 0.0 1.0 0.0 0.0\" zxPostCoefs=\"1 0 0 1 0 0\""),
      "t.flame")[0];
  EXPECT_EQ(flat.xforms.size(), 2u);
  EXPECT_STREQ(parse_error(flam3_flame("y", "yzCoefs=\"1 0 0 0.5 0 0.2\"")).what(),
               "t.flame: flame \"y\": xform 0: yzCoefs: a 3-D affine map (JWildfire) moves "
               "points out of the plane; ifsfx draws flames in the plane, where only the identity "
               "leaves them (got \"1 0 0 0.5 0 0.2\")");
}

TEST(flame_file, a_background_is_opaque_unless_the_file_makes_it_transparent) {
  const auto background = [](const std::string& attributes) {
    std::string xml = flam3_flame("b");
    const std::string given = "background=\"0.1 0.2 0.3\"";
    xml.replace(xml.find(given), given.size(), attributes);
    return parse_flames(xml, "t.flame")[0].tone.background;
  };
  EXPECT_EQ(background("background=\"0.1 0.2 0.3\""), (Rgba{0.1, 0.2, 0.3, 1}));  // flam3's
  EXPECT_EQ(background("background=\"0.1 0.2 0.3 0.25\""), (Rgba{0.1, 0.2, 0.3, 0.25}));
  EXPECT_EQ(background("background=\"0.8 0.8 0.8\" bg_transparency=\"1\""),
            (Rgba{0.8, 0.8, 0.8, 0}));  // JWildfire's
  EXPECT_EQ(background("background=\"0.8 0.8 0.8\" bg_transparency=\"0\""),
            (Rgba{0.8, 0.8, 0.8, 1}));
  EXPECT_EQ(background(""), (Rgba{0, 0, 0, 1}));
  const std::string corners =
      "background_type=\"GRADIENT_2X2_C\" background_ul=\"0.2 0.2 0.2\" "
      "background_ur=\"0.2 0.2 0.2\" background_cc=\"";
  EXPECT_EQ(background(corners + "0.2 0.2 0.2\""), (Rgba{0.2, 0.2, 0.2, 1}));  // one colour
  std::string xml = flam3_flame("g");
  const std::string given = "background=\"0.1 0.2 0.3\"";
  xml.replace(xml.find(given), given.size(), corners + "0.5 0 0\"");
  EXPECT_STREQ(parse_error(xml).what(),
               "t.flame: flame \"g\": background_type: a gradient background (JWildfire) is not "
               "drawn; one colour in every corner is (got \"GRADIENT_2X2_C, background_cc 0.5 0 "
               "0\")");
}

TEST(flame_file, symmetry_adds_flam3s_rotations_and_reflection_before_the_xforms) {
  std::string xml = flam3_flame();
  xml.insert(xml.find("<xform"), "<symmetry kind=\"-3\"/>\n");
  const Flame f = parse_flames(xml, "t.flame")[0];
  ASSERT_EQ(f.xforms.size(), 5u);  // reflection, 2 rotations, the 2 of the file
  EXPECT_EQ(f.xforms[0].pre, (AffineMap{.a = -1}));
  EXPECT_EQ(f.xforms[0].colour, 1);
  const AffineMap r = f.xforms[1].pre;  // by 120°: (1, 0) ↦ (−1/2, √3/2)
  EXPECT_POINT_NEAR(r(Point{1, 0}), -0.5, std::sqrt(3.0) / 2);
  EXPECT_EQ(f.xforms[1].colour, 0);
  EXPECT_EQ(f.xforms[2].colour, 1);
  EXPECT_EQ(f.xforms[1].colour_speed, 0);
  EXPECT_EQ(f.xforms[3].weight, 0.25);
}

TEST(flame_file, reads_palettes_as_rgba_hex_colors_data_and_color_elements) {
  std::string rgba =
      "<flame><xform weight=\"1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>"
      "<palette count=\"256\" format=\"RGBA\">";
  for (int i = 0; i < 256; ++i) rgba += "FF000080";
  const Flame a = parse_flames(rgba + "</palette></flame>", "t.flame")[0];
  EXPECT_EQ(a.palette.colours[7], (Rgba{1, 0, 0, 128 / 255.0}));

  std::string colors =
      "<flame><xform weight=\"1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>"
      "<colors count=\"256\" data=\"";
  for (int i = 0; i < 256; ++i) colors += "0000FF00";
  const Flame b = parse_flames(colors + "\"/></flame>", "t.flame")[0];
  EXPECT_EQ(b.palette.colours[200], (Rgba{0, 1, 0, 1}));

  std::string elements = "<flame><xform weight=\"1\" linear=\"1\" coefs=\"1 0 0 1 0 0\"/>";
  for (int i = 0; i < 256; ++i)
    elements +=
        "<color index=\"" + std::to_string(i) + "\" rgb=\"" + std::to_string(i) + " 0 255\"/>";
  const Flame c = parse_flames(elements + "</flame>", "t.flame")[0];
  EXPECT_EQ(c.palette.colours[51], (Rgba{0.2, 0, 1, 1}));
}

// Ember's palettes of N ≠ 256 entries: colour index c·(N − 1), resampled onto the renderer's 256
// entries as the mean over each entry's 1/256 of c (16 points at (k + (j + ½)/16)/256).
TEST(flame_file, reads_embers_palettes_of_other_lengths_by_their_colour_index) {
  const std::string head =
      "<flame name=\"p\" palette_mode=\"MODE\"><xform weight=\"1\" "
      "linear=\"1\" coefs=\"1 0 0 1 0 0\"/><palette count=\"N\" format=\"RGB\">";
  auto flame = [&](const std::string& mode, int n, const std::string& hex) {
    std::string xml = head;
    xml.replace(xml.find("MODE"), 4, mode);
    xml.replace(xml.find("\"N\""), 3, "\"" + std::to_string(n) + "\"");
    return parse_flames(xml + hex + "</palette></flame>", "t.flame")[0];
  };
  // 512 entries, 0..255 black, 256..511 white; step: white from c ≥ 256/511. Entry 128's points
  // c = (128 + (j + ½)/16)/256 reach it from j = 4: 12 of 16 white.
  std::string halves;
  for (int i = 0; i < 512; ++i) halves += i < 256 ? "000000" : "FFFFFF";
  const Flame a = flame("step", 512, halves);
  EXPECT_EQ(a.palette.colours[127], (Rgba{0, 0, 0, 1}));
  EXPECT_NEAR(a.palette.colours[128].g, 0.75, 1e-12);
  EXPECT_EQ(a.palette.colours[129], (Rgba{1, 1, 1, 1}));
  // 2 entries, black and white, linear: Ember's colour is c itself; entry k the mean
  // (k + ½)/256 of its interval.
  const Flame b = flame("linear", 2, "000000FFFFFF");
  EXPECT_NEAR(b.palette.colours[0].r, 0.5 / 256, 1e-12);
  EXPECT_NEAR(b.palette.colours[200].b, 200.5 / 256, 1e-12);
  EXPECT_STREQ(parse_error(head.substr(0, head.find("MODE")) +
                           "step\"><xform weight=\"1\" "
                           "linear=\"1\" coefs=\"1 0 0 1 0 0\"/><palette count=\"2.5\">"
                           "000000FFFFFF</palette></flame>")
                   .what(),
               "t.flame: flame \"p\": palette: count: a whole number of colours in [2, 65536] is "
               "needed (got \"2.5\")");
  std::string short_hex = halves.substr(0, 6 * 511);
  try {
    flame("step", 512, short_hex);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "t.flame: flame \"p\": palette: 512 colours of 6 hex digits are "
                 "needed (got 3066 digits)");
  }
}

TEST(flame_file, numbered_palettes_come_from_flam3s_library_with_their_hue) {
  if (!fs::exists(kDefaultPaletteFile)) GTEST_SKIP() << "flam3-palette is not installed";
  const std::string xml =
      "<flame palette=\"0\"><xform weight=\"1\" linear=\"1\" "
      "coefs=\"1 0 0 1 0 0\"/></flame>";
  const Flame f = parse_flames(xml, "t.flame")[0];
  EXPECT_EQ(f.palette.source, PaletteSource::library);
  EXPECT_EQ(f.palette.index, 0);
  // flam3-palettes.xml palette 0 ("south-sea-bather") starts with 00b9eaeb
  EXPECT_EQ(f.palette.colours[0], (Rgba{0xb9 / 255.0, 0xea / 255.0, 0xeb / 255.0, 1}));
  // Half a turn of hue: (h + 3) mod 6 keeps value and saturation: the complement of an
  // RGB colour with channels (mx, m1, mn) is (mn, mx + mn − m1, mx).
  const std::string turned =
      "<flame palette=\"0\" hue=\"0.5\"><xform weight=\"1\" linear=\"1\" "
      "coefs=\"1 0 0 1 0 0\"/></flame>";
  const Rgba c = parse_flames(turned, "t.flame")[0].palette.colours[0];
  EXPECT_NEAR(c.r, 0xeb / 255.0, 1e-12);
  EXPECT_NEAR(c.g, (0xeb + 0xb9 - 0xea) / 255.0, 1e-12);
  EXPECT_NEAR(c.b, 0xb9 / 255.0, 1e-12);
}

TEST(flame_file, a_missing_palette_library_is_a_clear_error) {
  const std::string xml =
      "<flame name=\"n\" palette=\"3\"><xform weight=\"1\" linear=\"1\" "
      "coefs=\"1 0 0 1 0 0\"/></flame>";
  try {
    parse_flames(xml, "t.flame", {.palette_file = "/nonexistent/flam3-palettes.xml"});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_STREQ(e.what(),
                 "/nonexistent/flam3-palettes.xml: flam3's palette library is needed for palette "
                 "3 (Debian: flam3-palette) (got no such file)");
  }
}

TEST(flame_file, errors_name_the_file_the_flame_and_the_attribute) {
  const Error not_xml = parse_error("<flame><xform></flame>");
  EXPECT_EQ(not_xml.kind(), ErrorKind::parse);
  EXPECT_STREQ(not_xml.what(), "t.flame:1: not flame XML: Start-end tags mismatch");
  EXPECT_STREQ(parse_error("just text").what(),
               "t.flame: a flame file needs a <flame> element (got none)");
  EXPECT_STREQ(parse_error("<flame name=\"e\">" + grey_palette() + "</flame>").what(),
               "t.flame: flame \"e\": xform: at least one <xform> is needed");
  EXPECT_STREQ(parse_error(flam3_flame("w", "swirl=\"nan\"")).what(),
               "t.flame: flame \"w\": xform 0: swirl: a finite number is needed (got \"nan\")");
  std::string bad_coef = flam3_flame("c");
  bad_coef.replace(bad_coef.find("coefs=\"1 2 3"), 14, "coefs=\"1 2 inf");
  EXPECT_STREQ(parse_error(bad_coef).what(),
               "t.flame: flame \"c\": xform 0: coefs: a finite number is needed (got \"inf\")");
  EXPECT_STREQ(parse_error(flam3_flame("u", "no_such_one=\"0.5\" no_such_one_size=\"1\"")).what(),
               "t.flame: flame \"u\": xform 0: unknown variation \"no_such_one\"");
  EXPECT_STREQ(parse_error(flam3_flame("q", "julian_foo=\"1\"")).what(),
               "t.flame: flame \"q\": xform 0: unknown parameter \"julian_foo\" of variation "
               "\"julian\"");
  std::string short_palette = flam3_flame("s");
  short_palette.replace(short_palette.find("</palette>") - 7, 7, "");
  EXPECT_STREQ(parse_error(short_palette).what(),
               "t.flame: flame \"s\": palette: 256 colours of 6 hex digits are needed (got "
               "1530 digits)");  // one colour short
}

TEST(flame_file, picks_a_flame_by_name_or_index_and_needs_a_pick_among_several) {
  const fs::path p =
      write_file("pick.flame", "<flames>" + flam3_flame("a") + flam3_flame("b") + "</flames>");
  EXPECT_EQ(read_flame(p.string() + ":b").name, "b");
  EXPECT_EQ(read_flame(p.string() + ":0").name, "a");
  EXPECT_EQ(read_flames(p.string()).size(), 2u);
  try {
    read_flame(p.string());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::not_found);
    EXPECT_EQ(std::string(e.what()), p.string() + ": holds 2 flames: pick one as " + p.string() +
                                         ":NAME or " + p.string() + ":INDEX (0:a, 1:b)");
  }
  EXPECT_THROW(read_flame(p.string() + ":c"), Error);
  const fs::path one = write_file("one.flame", flam3_flame("solo"));
  EXPECT_EQ(read_flame(one.string()).name, "solo");
  EXPECT_EQ(split_flame_spec("dir/x.flame:NAME").path, "dir/x.flame");
  EXPECT_EQ(split_flame_spec("dir/x.flame:NAME").selector, "NAME");
  EXPECT_TRUE(is_flame_spec("a.flam3:2"));
  EXPECT_FALSE(is_flame_spec("fern.toml"));
}

TEST(flame_file, lists_each_flame_with_the_reason_it_cannot_be_rendered) {
  const fs::path p =
      write_file("list.flame",
                 flam3_flame("good") + flam3_flame("bad", "no_such_one=\"1\"") + flam3_flame(""));
  const std::vector<FlameEntry> list = list_flames(p.string());
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].name, "good");
  EXPECT_EQ(list[0].xforms, 2u);
  EXPECT_TRUE(list[0].problem.empty());
  EXPECT_EQ(list[1].problem,
            p.string() + ": flame \"bad\": xform 0: unknown variation \"no_such_one\"");
  EXPECT_EQ(list[2].index, 2u);
}

TEST(flame_file, reads_debians_test_flam3) {
  const char* path = "/usr/share/flam3/test.flam3";
  if (!fs::exists(path) || !fs::exists(kDefaultPaletteFile)) GTEST_SKIP() << "no flam3-utils";
  const std::vector<Flame> flames = read_flames(path);
  ASSERT_EQ(flames.size(), 2u);
  EXPECT_EQ(flames[0].xforms.size(), 4u);
  EXPECT_EQ(flames[0].palette.index, 15);
  EXPECT_NEAR(flames[0].palette.hue, 0.22851, 1e-12);
  EXPECT_EQ(variation(flames[0].xforms[0].variations[0].id).name, "spherical");
}

TEST(flame_file, reads_flam3_genome_random_genomes) {
  if (std::system("command -v flam3-genome > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "flam3-genome (flam3-utils) is not installed";
  // tries=1: no colour-improving search (it renders, seconds a genome); five genomes.
  // The process id in the name: two test runs at once (two checkouts) wrote one file.
  const fs::path p =
      fs::temp_directory_path() / ("ifsfx_flame_genomes_" + std::to_string(getpid()) + ".flam3");
  const std::string cmd =
      "env seed=5 repeat=5 tries=1 flam3-genome > " + p.string() + " 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::vector<Flame> flames = read_flames(p.string());
  ASSERT_EQ(flames.size(), 5u);
  for (const Flame& f : flames) EXPECT_GE(f.xforms.size(), 2u);
}

}  // namespace
}  // namespace ifsfx::flame
