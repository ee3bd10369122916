// SPDX-License-Identifier: Apache-2.0
// A flame as the studio's page edits it (studio/flame_doc.h): the document reads back as the same
// flame, its maps are the pre-affine maps in the editor plane (the flame plane turned by the
// camera and flipped to y up), a view is shown by the camera made for it, and a bad field is
// named.
#include "studio/flame_doc.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "flame/flame_file.h"
#include "flame/flame_write.h"
#include "ifs/error.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

// A flame with a bit of everything the document carries: a post map, xaos, pre_ and post_
// variations with parameters, a final xform, a camera off centre, an inline palette.
flame::Flame sample_flame(double rotate) {
  std::string xml = R"(<flame name="doc" size="120 90" center="0.25 -0.5" scale="40" zoom="0.5"
    rotate=")" + std::to_string(rotate) +
                    R"(" quality="30" oversample="2" filter="0.7" brightness="3" gamma="2.2"
    vibrancy="0.8" background="0.1 0.2 0.3" estimator_radius="5">
  <xform weight="0.7" color="0.2" color_speed="0.3" opacity="0.9" chaos="1 0.5" linear="0.5"
    julian="0.5" julian_power="3" julian_dist="-1" pre_blur="0.1" coefs="0.6 0.2 -0.2 0.6 0.3 -0.1"/>
  <xform weight="0.3" color="0.9" spherical="1" post_swirl="0.2" coefs="0.5 -0.3 0.3 0.5 -0.4 0.2"
    post="1 0 0.1 1 0.1 0"/>
  <finalxform color="0.5" linear="1" coefs="1.1 0 0 1.1 0 0"/>
  <palette count="256" format="RGB">)";
  for (int k = 0; k < 256; ++k) xml += fmt::format("{:02X}{:02X}{:02X}", k, 255 - k, (7 * k) % 256);
  xml += "</palette></flame>";
  return flame::parse_flames(xml, "doc.flame").at(0);
}

TEST(flame_doc, a_document_reads_back_as_the_same_flame_and_its_xml) {
  const flame::Flame f = sample_flame(0);
  const StudioFlame back = flame_from_json(flame_to_json(f));
  EXPECT_EQ(back.flame, f);
  EXPECT_EQ(back.xml, flame::flame_xml(f));
  // Through the JSON text, as the page sends it.
  EXPECT_EQ(flame_from_json(json::parse(flame_to_json(f).dump())).flame, f);
}

TEST(flame_doc, the_maps_are_the_pre_affine_maps_flipped_to_y_up) {
  // coefs "a b c d e f": x' = a·x + c·y + e, y' = b·x + d·y + f with y down; with y up,
  // x' = a·x − c·y + e, y' = −b·x + d·y − f.
  const json doc = flame_to_json(sample_flame(0));
  EXPECT_EQ(doc["maps"][0], json({0.6, 0.2, -0.2, 0.6, 0.3, 0.1}));
  EXPECT_EQ(doc["flame"]["xforms"][1]["post"], json({1.0, 0.0, 0.1, 1.0, 0.1, 0.0}));
}

TEST(flame_doc, a_turned_camera_turns_the_editor_plane_with_it) {
  const flame::Flame f = sample_flame(30);
  const json doc = flame_to_json(f);
  // The editor plane's q = S·R(30°)·p: the map in the editor takes q(p) to q(pre(p)).
  const double t = 30 * std::numbers::pi / 180, c = std::cos(t), s = std::sin(t);
  const auto q = [&](Point p) { return Point{c * p.x - s * p.y, -(s * p.x + c * p.y)}; };
  const AffineMap m = AffineMap::from_coefficients(doc["maps"][1].get<std::array<double, 6>>());
  for (const Point p : {Point{0, 0}, Point{1, 0}, Point{0.3, -2}}) {
    const Point want = q(f.xforms[1].pre(p)), got = m(q(p));
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
  }
  // Back to the flame plane to rounding.
  const flame::Flame back = flame_from_json(doc).flame;
  for (std::size_t i = 0; i < f.xforms.size(); ++i) {
    const auto want = f.xforms[i].pre.coefficients(), got = back.xforms[i].pre.coefficients();
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(got[k], want[k], 1e-15) << "xform " << i << " " << k;
  }
}

TEST(flame_doc, a_view_is_shown_by_the_camera_made_for_it) {
  const flame::Flame f = sample_flame(30);
  // Its own framing: the camera's centre in the editor plane, size / (scale · 2^zoom) across.
  const Box own = camera_view(studio_camera(f.camera, {240, 180}, std::nullopt));
  const double ppu = 40 * std::sqrt(2.0) * 2;  // twice the pixels for the same framing
  EXPECT_NEAR(own.width(), 240 / ppu, 1e-12);
  EXPECT_NEAR(own.height(), 180 / ppu, 1e-12);
  const double t = 30 * std::numbers::pi / 180;
  EXPECT_NEAR((own.x0 + own.x1) / 2, std::cos(t) * 0.25 + std::sin(t) * 0.5, 1e-12);
  EXPECT_NEAR((own.y0 + own.y1) / 2, -(std::sin(t) * 0.25 - std::cos(t) * 0.5), 1e-12);
  const Box view{-1, 0.5, 2, 2.75};  // the page's shape, 4:3
  const Box shown = camera_view(studio_camera(f.camera, {160, 120}, view));
  EXPECT_NEAR(shown.x0, view.x0, 1e-12);
  EXPECT_NEAR(shown.y0, view.y0, 1e-12);
  EXPECT_NEAR(shown.x1, view.x1, 1e-12);
  EXPECT_NEAR(shown.y1, view.y1, 1e-12);
}

TEST(flame_doc, a_bad_field_is_named) {
  const json doc = flame_to_json(sample_flame(0));
  const auto message = [](const json& d) {
    try {
      flame_from_json(d);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  json d = doc;
  d["flame"]["xforms"][1]["weight"] = "x";
  EXPECT_EQ(message(d), "flame.xforms[1].weight: must be a finite number (got \"x\")");
  d = doc;
  d["flame"]["xforms"][0]["variations"][1]["name"] = "nope";
  EXPECT_EQ(message(d),
            "flame.xforms[0].variations[1].name: a variation of GET /api/flame/variations (got "
            "\"nope\")");
  d = doc;
  d["flame"]["xforms"][0]["variations"].push_back({{"name", "linear"}});
  EXPECT_EQ(message(d),
            "xform 0: variation linear twice in one list: a flame file holds one of each");
  d = doc;
  d["flame"]["xforms"][1]["weight"] = -1;  // the reader's own rule, with the reader's message
  EXPECT_EQ(message(d), "flame: flame \"doc\": xform 1: weight: must be >= 0 (got \"-1\")");
}

}  // namespace
}  // namespace ifsfx::app
