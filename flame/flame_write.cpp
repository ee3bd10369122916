// SPDX-License-Identifier: Apache-2.0
#include "flame/flame_write.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "flame/variations.h"
#include "ifs/error.h"
#include "ifs/render.h"
#include "ifs/view.h"

namespace ifsfx::flame {
namespace {

// Shortest text that reads back as the same double ({fmt}'s default).
std::string num(double v) {
  return fmt::format("{}", v == 0 ? 0.0 : v);
}

std::string escaped(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      // A literal tab or line break in an attribute reads back as a space (XML's attribute-value
      // normalisation); a character reference survives it.
      case '\t':
        out += "&#9;";
        break;
      case '\n':
        out += "&#10;";
        break;
      case '\r':
        out += "&#13;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string coefs(const AffineMap& m) {
  const std::array<double, 6> k = to_flam3_coefs(m);
  return fmt::format("{} {} {} {} {} {}", num(k[0]), num(k[1]), num(k[2]), num(k[3]), num(k[4]),
                     num(k[5]));
}

void write_terms(std::string& out, const std::string& what, const std::vector<VariationTerm>& terms,
                 const char* prefix) {
  std::set<std::uint32_t> seen;
  for (const VariationTerm& t : terms) {
    const Variation& v = variation(t.id);
    if (!seen.insert(t.id).second)
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: variation {} twice in one list: a flame file holds one of each",
                              what, v.name));
    if (t.params.size() != v.parameters.size())
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("{}: variation {}: {} parameters are needed (got {})", what, v.name,
                              v.parameters.size(), t.params.size()));
    const std::string p = v.place == VariationPlace::pre_only ? "" : prefix;
    out += fmt::format(" {}{}=\"{}\"", p, v.name, num(t.weight));
    for (std::size_t k = 0; k < t.params.size(); ++k)
      out += fmt::format(" {}{}=\"{}\"", p, v.parameters[k].name, num(t.params[k]));
  }
}

std::string xform_xml(const Xform& xf, const std::string& what, bool is_final) {
  std::string out =
      is_final ? "   <finalxform" : fmt::format("   <xform weight=\"{}\"", num(xf.weight));
  out += fmt::format(" color=\"{}\" color_speed=\"{}\"", num(xf.colour), num(xf.colour_speed));
  // Apophysis 7X and older flam3 read the speed as symmetry σ = 1 − 2s.
  out +=
      fmt::format(" symmetry=\"{}\" opacity=\"{}\"", num(1 - 2 * xf.colour_speed), num(xf.opacity));
  if (!xf.name.empty()) out += fmt::format(" name=\"{}\"", escaped(xf.name));
  if (!xf.chaos.empty()) {
    std::string row;
    for (double c : xf.chaos) {
      if (!row.empty()) row += ' ';
      row += num(c);
    }
    out += fmt::format(" chaos=\"{}\"", row);
  }
  write_terms(out, what, xf.pre_variations, "pre_");
  write_terms(out, what, xf.variations, "");
  write_terms(out, what, xf.post_variations, "post_");
  out += fmt::format(" coefs=\"{}\"", coefs(xf.pre));
  if (xf.post) out += fmt::format(" post=\"{}\"", coefs(*xf.post));
  return out + "/>\n";
}

int byte(double v) {
  return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
}

std::string palette_xml(const Palette& pal) {
  const bool alpha = std::any_of(pal.colours.begin(), pal.colours.end(),
                                 [](const Rgba& c) { return byte(c.a) != 255; });
  std::string out = fmt::format("<palette count=\"256\" format=\"{}\">\n", alpha ? "RGBA" : "RGB");
  for (std::size_t k = 0; k < 256; ++k) {
    const Rgba& c = pal.colours[k];
    out += fmt::format("{:02X}{:02X}{:02X}", byte(c.r), byte(c.g), byte(c.b));
    if (alpha) out += fmt::format("{:02X}", byte(c.a));
    if (k % 8 == 7) out += "\n";
  }
  return out + "</palette>\n";
}

std::string flame_attributes(const Flame& f) {
  const Camera& c = f.camera;
  const ToneMapping& t = f.tone;
  const Filtering& s = f.filtering;
  std::string out = fmt::format(
      "<flame version=\"ifsfx\" name=\"{}\" size=\"{} {}\" center=\"{} {}\" scale=\"{}\" "
      "zoom=\"{}\" rotate=\"{}\" supersample=\"{}\" filter=\"{}\" filter_shape=\"{}\" "
      "quality=\"{}\"",
      escaped(f.name), c.width, c.height, num(c.center.x), num(c.center.y), num(c.scale),
      num(c.zoom), num(c.rotate), s.supersample, num(s.filter_radius), escaped(s.filter_shape),
      num(f.quality));
  // A fourth number only for a background that is not opaque (flam3 reads three).
  std::string alpha;
  if (t.background.a != 1) alpha = fmt::format(" {}", num(t.background.a));
  out += fmt::format(
      " background=\"{} {} {}{}\" brightness=\"{}\" gamma=\"{}\" gamma_threshold=\"{}\" "
      "vibrancy=\"{}\" highlight_power=\"{}\" contrast=\"{}\" estimator_radius=\"{}\" "
      "estimator_minimum=\"{}\" estimator_curve=\"{}\" palette_mode=\"{}\"",
      num(t.background.r), num(t.background.g), num(t.background.b), alpha, num(t.brightness),
      num(t.gamma), num(t.gamma_threshold), num(t.vibrancy), num(t.highlight_power),
      num(t.contrast), num(s.estimator_radius), num(s.estimator_minimum), num(s.estimator_curve),
      f.palette.mode == PaletteMode::linear ? "linear" : "step");
  if (c.zpos != 0 || c.perspective != 0 || c.yaw != 0 || c.pitch != 0 || c.depth_blur != 0)
    out += fmt::format(
        " cam_zpos=\"{}\" cam_persp=\"{}\" cam_yaw=\"{}\" cam_pitch=\"{}\" "
        "cam_dof=\"{}\"",
        num(c.zpos), num(c.perspective), num(c.yaw), num(c.pitch), num(c.depth_blur));
  if (f.palette.source == PaletteSource::library)
    out += fmt::format(" palette=\"{}\" hue=\"{}\"", f.palette.index, num(f.palette.hue));
  else if (f.palette.hue != 0)
    out += fmt::format(" hue=\"{}\"", num(f.palette.hue));
  return out + ">\n";
}

}  // namespace

std::string flame_xml(const Flame& flame) {
  std::string out = flame_attributes(flame);
  for (std::size_t i = 0; i < flame.xforms.size(); ++i)
    out += xform_xml(flame.xforms[i], fmt::format("xform {}", i), false);
  if (flame.final_xform) out += xform_xml(*flame.final_xform, "finalxform", true);
  if (flame.palette.source != PaletteSource::library) out += palette_xml(flame.palette);
  return out + "</flame>\n";
}

std::string flames_xml(std::span<const Flame> flames) {
  if (flames.size() == 1) return flame_xml(flames[0]);
  std::string out = "<flames>\n";
  for (const Flame& f : flames) out += flame_xml(f);
  return out + "</flames>\n";
}

}  // namespace ifsfx::flame
