// SPDX-License-Identifier: Apache-2.0
// One <flame> element: its attributes (camera, tone mapping, filtering), its xforms, flam3's
// <symmetry kind=N> expanded as flam3 does, and the checks a renderer relies on.
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "flame/detail/flame_xml.h"
#include "flame/variations.h"

namespace ifsfx::flame::detail {
namespace {

constexpr double kMaxSide = 1 << 16;  // pixels: past any picture a flame file asks for

void read_camera(const Where& at, const pugi::xml_node& f, Camera& cam) {
  if (const auto a = f.attribute("size")) {
    const std::vector<double> s = numbers(at, "size", a.value(), 2);
    if (s[0] < 1 || s[1] < 1 || s[0] > kMaxSide || s[1] > kMaxSide || s[0] != std::floor(s[0]) ||
        s[1] != std::floor(s[1]))
      at.fail("size", "two whole numbers of pixels in [1, 65536] are needed", a.value());
    cam.width = static_cast<int>(s[0]);
    cam.height = static_cast<int>(s[1]);
  }
  if (const auto a = f.attribute("center")) {
    const std::vector<double> c = numbers(at, "center", a.value(), 2);
    cam.center = {c[0], c[1]};
  }
  cam.scale = number_or(at, f, "scale", cam.scale);
  if (cam.scale <= 0) at.fail("scale", "must be > 0", f.attribute("scale").value());
  // JWildfire's camera zoom multiplies the pixels per unit (its density normalisation uses the
  // product too), so it is a scale.
  const double cam_zoom = number_or(at, f, "cam_zoom", 1);
  if (cam_zoom <= 0) at.fail("cam_zoom", "must be > 0", f.attribute("cam_zoom").value());
  cam.scale *= cam_zoom;
  cam.zoom = number_or(at, f, "zoom", 0);
  if (std::abs(cam.zoom) > 50) at.fail("zoom", "must be in [-50, 50]", f.attribute("zoom").value());
  cam.rotate = number_or(at, f, "rotate", 0);
  cam.zpos = number_or(at, f, "cam_zpos", 0);
  cam.perspective = number_or(at, f, "cam_persp", 0);
  cam.yaw = number_or(at, f, "cam_yaw", 0);
  cam.pitch = number_or(at, f, "cam_pitch", 0);
  cam.depth_blur = number_or(at, f, "cam_dof", 0);
}

// JWildfire's gradient backgrounds (background_type GRADIENT_2X2, GRADIENT_2X2_C): corner
// colours (and a centre one) blended over the picture. One colour throughout is the background;
// a gradient is refused rather than drawn as one colour.
void read_jwildfire_gradient(const Where& at, const pugi::xml_node& f, ToneMapping& t) {
  const std::string_view type = f.attribute("background_type").value();
  if (!type.starts_with("GRADIENT")) return;
  std::optional<std::vector<double>> first;
  for (const char* name :
       {"background_ul", "background_ur", "background_ll", "background_lr", "background_cc"}) {
    const auto a = f.attribute(name);
    if (!a) continue;
    const std::vector<double> c = numbers(at, name, a.value(), 3);
    if (!first) first = c;
    if (c != *first)
      at.fail("background_type",
              "a gradient background (JWildfire) is not drawn; one colour in every corner is",
              std::string(type) + ", " + name + " " + a.value());
  }
  if (first) t.background = {(*first)[0], (*first)[1], (*first)[2], t.background.a};
}

void read_tone(const Where& at, const pugi::xml_node& f, ToneMapping& t) {
  t.brightness = number_or(at, f, "brightness", t.brightness);
  t.gamma = number_or(at, f, "gamma", t.gamma);
  if (t.gamma <= 0) at.fail("gamma", "must be > 0", f.attribute("gamma").value());
  t.gamma_threshold = number_or(at, f, "gamma_threshold", t.gamma_threshold);
  t.vibrancy = number_or(at, f, "vibrancy", t.vibrancy);
  t.highlight_power = number_or(at, f, "highlight_power", t.highlight_power);
  t.contrast = number_or(at, f, "contrast", t.contrast);
  if (const auto a = f.attribute("background")) {
    const std::vector<double> b = numbers(at, "background", a.value());
    if (b.size() != 3 && b.size() != 4)
      at.fail("background", "3 numbers (RGB in [0, 1]) are needed", a.value());
    // Three numbers: opaque, as flam3-render (transparency=0), Apophysis and JWildfire render by
    // default; a fourth is the background's alpha (Ember).
    t.background = {b[0], b[1], b[2], b.size() == 4 ? b[3] : 1.0};
  }
  read_jwildfire_gradient(at, f, t);
  // JWildfire's transparent background.
  const std::string_view clear = f.attribute("bg_transparency").value();
  if (clear == "1" || clear == "true") t.background.a = 0;
}

void read_filtering(const Where& at, const pugi::xml_node& f, Flame& flame) {
  Filtering& s = flame.filtering;
  const char* ss = f.attribute("supersample") ? "supersample" : "oversample";
  const double n = number_or(at, f, ss, 1);
  if (n < 1 || n > 64 || n != std::floor(n))
    at.fail(ss, "a whole number in [1, 64] is needed", f.attribute(ss).value());
  s.supersample = static_cast<int>(n);
  s.filter_radius = number_or(at, f, "filter", s.filter_radius);
  if (s.filter_radius < 0) at.fail("filter", "must be >= 0", f.attribute("filter").value());
  if (const auto a = f.attribute("filter_shape")) s.filter_shape = a.value();
  s.estimator_radius = number_or(at, f, "estimator_radius", s.estimator_radius);
  s.estimator_minimum = number_or(at, f, "estimator_minimum", s.estimator_minimum);
  s.estimator_curve = number_or(at, f, "estimator_curve", s.estimator_curve);
  if (s.estimator_radius < 0 || s.estimator_minimum < 0)
    at.fail("estimator_radius", "the estimator's radii must be >= 0");
  flame.quality = number_or(at, f, "quality", flame.quality);
  if (flame.quality <= 0) at.fail("quality", "must be > 0", f.attribute("quality").value());
}

Xform symmetry_xform(double angle, bool reflect, double colour) {
  Xform xf;
  xf.weight = 1;
  xf.colour = colour;
  xf.colour_speed = 0;
  const double c = std::cos(angle), s = std::sin(angle);
  xf.pre = reflect ? AffineMap{.a = -1} : AffineMap{.a = c, .b = -s, .c = s, .d = c};
  const Variation* linear = find_variation("linear");
  xf.variations = {{.id = linear->id, .weight = 1}};
  return xf;
}

// flam3's <symmetry kind=k>: k > 0 adds the rotations by 2πj/k (j = 1 … k−1), k < 0 also a
// reflection x ↦ −x first; weight 1, colour speed 0, the rotations' colours spread over [0, 1].
// Added before the flame's own xforms, as flam3 does.
std::vector<Xform> symmetry_xforms(const Where& at, const pugi::xml_node& f) {
  std::vector<Xform> out;
  for (const pugi::xml_node s : f.children("symmetry")) {
    const double k = number(at, "symmetry: kind", s.attribute("kind").value());
    if (k != std::floor(k) || std::abs(k) > 64)
      at.fail("symmetry: kind", "a whole number in [-64, 64] is needed",
              s.attribute("kind").value());
    const int n = static_cast<int>(std::abs(k));
    if (k < 0) out.push_back(symmetry_xform(0, true, 1));
    for (int j = 1; j < n; ++j)
      out.push_back(
          symmetry_xform(2 * std::numbers::pi * j / n, false, n > 2 ? (j - 1.0) / (n - 2) : 0.0));
  }
  return out;
}

void check(const Where& at, const Flame& flame) {
  if (flame.xforms.empty()) at.fail("xform", "at least one <xform> is needed");
  double total = 0;
  for (const Xform& xf : flame.xforms) total += xf.weight;
  if (!(total > 0) || !std::isfinite(total))
    at.fail("xform: weight", fmt::format("the xforms' weights must have a positive finite sum "
                                         "(got {})",
                                         total));
  for (std::size_t i = 0; i < flame.xforms.size(); ++i)
    if (flame.xforms[i].chaos.size() > flame.xforms.size())
      at.fail(fmt::format("xform {}: chaos", i),
              fmt::format("one weight per xform is needed, {} at most (got {})",
                          flame.xforms.size(), flame.xforms[i].chaos.size()));
}

}  // namespace

Flame parse_flame(const Where& at, const pugi::xml_node& f, const FlameReadOptions& options) {
  Flame flame;
  flame.name = f.attribute("name").value();
  read_camera(at, f, flame.camera);
  read_tone(at, f, flame.tone);
  read_filtering(at, f, flame);
  flame.xforms = symmetry_xforms(at, f);
  const std::size_t first = flame.xforms.size();
  for (const pugi::xml_node x : f.children("xform"))
    flame.xforms.push_back(
        parse_xform(at, x, fmt::format("xform {}", flame.xforms.size() - first), false));
  std::size_t finals = 0;
  for (const pugi::xml_node x : f.children("finalxform")) {
    if (++finals > 1) at.fail("finalxform", "one final xform at most");
    flame.final_xform = parse_xform(at, x, "finalxform", true);
  }
  flame.palette = parse_palette(at, f, options);
  check(at, flame);
  return flame;
}

}  // namespace ifsfx::flame::detail
