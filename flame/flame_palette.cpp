// SPDX-License-Identifier: Apache-2.0
// A flame's 256 colours: inline (<palette count="N" format="RGB|RGBA">hex</palette>, flam3
// 2.x's <colors count="256" data="00RRGGBB…"/>, or one <color index="i" rgb="r g b"/> per entry),
// else palette="N" of flam3's library (flam3-palettes.xml, entries <palette number="N"
// data="00RRGGBB…"/>) rotated in hue by `hue` turns. Ember's palettes of other lengths are
// resampled onto 256 entries (docs/flames.md, "Palettes of other lengths").
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "flame/detail/flame_xml.h"
#include "ifs/error.h"

namespace ifsfx::flame::detail {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The hex digits of `text` (white space skipped), or nothing when another character is there.
std::optional<std::string> hex_digits(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (hex_digit(c) < 0) return std::nullopt;
    out.push_back(c);
  }
  return out;
}

// `n` colours of `per` hex digits each: RGB (6), RGBA (8), or flam3's 00RRGGBB (8, skip 2).
std::optional<std::vector<Rgba>> decode(std::string_view text, std::size_t n, int per,
                                        bool leading_pad) {
  const std::optional<std::string> d = hex_digits(text);
  if (!d || d->size() != n * per) return std::nullopt;
  auto byte = [&](std::size_t i) {
    return (hex_digit((*d)[i]) * 16 + hex_digit((*d)[i + 1])) / 255.0;
  };
  std::vector<Rgba> c(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t o = k * per + (leading_pad ? 2 : 0);
    c[k] = {byte(o), byte(o + 2), byte(o + 4), per == 8 && !leading_pad ? byte(o + 6) : 1.0};
  }
  return c;
}

std::array<Rgba, 256> first_256(const std::vector<Rgba>& c) {
  std::array<Rgba, 256> out{};
  std::copy_n(c.begin(), 256, out.begin());
  return out;
}

// Ember's colour of a palette of N entries at colour coordinate c: index c·(N − 1) (Ember's
// Renderer::Accumulate), the entry below it (step) or the two around it mixed (linear).
Rgba ember_colour(const std::vector<Rgba>& e, double c, PaletteMode mode) {
  const double at = std::clamp(c, 0.0, 1.0) * static_cast<double>(e.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(at), e.size() - 1);
  if (mode == PaletteMode::step || i + 1 == e.size()) return e[i];
  const double f = at - static_cast<double>(i);
  const Rgba &a = e[i], &b = e[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b),
          a.a + f * (b.a - a.a)};
}

// A palette of N ≠ 256 entries onto the renderer's 256 (flam3's index ⌊256·c⌋): entry k is the
// mean of Ember's colour over its coordinates c ∈ [k/256, (k + 1)/256), taken at 16 points,
// which is what a histogram bin sums when the coordinate is spread over that interval.
std::array<Rgba, 256> resample(const std::vector<Rgba>& e, PaletteMode mode) {
  constexpr int kSamples = 16;
  std::array<Rgba, 256> out{};
  for (std::size_t k = 0; k < 256; ++k) {
    Rgba sum{0, 0, 0, 0};
    for (int j = 0; j < kSamples; ++j) {
      const Rgba c = ember_colour(e, (static_cast<double>(k) + (j + 0.5) / kSamples) / 256, mode);
      sum = {sum.r + c.r, sum.g + c.g, sum.b + c.b, sum.a + c.a};
    }
    out[k] = {sum.r / kSamples, sum.g / kSamples, sum.b / kSamples, sum.a / kSamples};
  }
  return out;
}

// <palette count="N" format="RGB|RGBA">hex</palette>: flam3 and Apophysis write 256 colours,
// Ember and Fractorium any count (512, 1024, ...); no count means 256.
std::array<Rgba, 256> palette_element(const Where& at, const pugi::xml_node& p, PaletteMode mode) {
  const std::string_view format = p.attribute("format").value();
  std::size_t n = 256;
  if (const auto count = p.attribute("count")) {
    const double c = number(at, "palette: count", count.value());
    if (c < 2 || c > 65536 || c != std::floor(c))
      at.fail("palette: count", "a whole number of colours in [2, 65536] is needed", count.value());
    n = static_cast<std::size_t>(c);
  }
  const int per = format == "RGBA" || format == "rgba" ? 8 : 6;
  if (!format.empty() && per == 6 && format != "RGB" && format != "rgb")
    at.fail("palette: format", "RGB or RGBA is needed", format);
  const std::optional<std::string> digits = hex_digits(p.child_value());
  if (!digits) at.fail("palette", "hex digits are needed", p.child_value());
  const std::optional<std::vector<Rgba>> c = decode(*digits, n, per, false);
  if (!c)
    at.fail("palette", fmt::format("{} colours of {} hex digits are needed (got {} digits)", n, per,
                                   digits->size()));
  return n == 256 ? first_256(*c) : resample(*c, mode);
}

std::array<Rgba, 256> color_elements(const Where& at, const pugi::xml_node& flame) {
  std::array<Rgba, 256> c{};
  std::array<bool, 256> seen{};
  for (const pugi::xml_node e : flame.children("color")) {
    const double i = number(at, "color: index", e.attribute("index").value());
    if (i < 0 || i > 255 || i != std::floor(i))
      at.fail("color: index", "an integer in [0, 255] is needed", e.attribute("index").value());
    const pugi::xml_attribute rgba = e.attribute("rgba");
    const std::vector<double> v = rgba ? numbers(at, "color: rgba", rgba.value(), 4)
                                       : numbers(at, "color: rgb", e.attribute("rgb").value(), 3);
    const auto k = static_cast<std::size_t>(i);
    c[k] = {v[0] / 255, v[1] / 255, v[2] / 255, v.size() == 4 ? v[3] / 255 : 1.0};
    seen[k] = true;
  }
  for (std::size_t k = 0; k < 256; ++k)
    if (!seen[k]) at.fail("color", fmt::format("256 entries are needed, index {} is missing", k));
  return c;
}

// flam3's hue rotation: RGB → HSV (h in [0, 6)), h + 6·hue, back.
Rgba rotate_hue(Rgba c, double hue) {
  const double mx = std::max({c.r, c.g, c.b}), mn = std::min({c.r, c.g, c.b}), d = mx - mn;
  if (d <= 0) return c;
  double h = c.r == mx ? (c.g - c.b) / d : c.g == mx ? 2 + (c.b - c.r) / d : 4 + (c.r - c.g) / d;
  h = std::fmod(h + 6 * hue, 6.0);
  if (h < 0) h += 6;
  const double s = d / mx, v = mx, f = h - std::floor(h);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (static_cast<int>(std::floor(h)) % 6) {
    case 0:
      return {v, t, p, c.a};
    case 1:
      return {q, v, p, c.a};
    case 2:
      return {p, v, t, c.a};
    case 3:
      return {p, q, v, c.a};
    case 4:
      return {t, p, v, c.a};
    default:
      return {v, p, q, c.a};
  }
}

}  // namespace

Palette parse_palette(const Where& at, const pugi::xml_node& flame,
                      const FlameReadOptions& options) {
  Palette pal;
  pal.mode = std::string_view(flame.attribute("palette_mode").value()) == "linear"
                 ? PaletteMode::linear
                 : PaletteMode::step;
  pal.hue = number_or(at, flame, "hue", 0);
  if (const pugi::xml_node p = flame.child("palette")) {
    pal.colours = palette_element(at, p, pal.mode);
  } else if (const pugi::xml_node p2 = flame.child("colors")) {
    const std::optional<std::vector<Rgba>> c = decode(p2.attribute("data").value(), 256, 8, true);
    if (!c)
      at.fail("colors: data", "256 colours of 8 hex digits are needed",
              p2.attribute("data").value());
    pal.colours = first_256(*c);
  } else if (flame.child("color")) {
    pal.colours = color_elements(at, flame);
  } else if (const auto n = flame.attribute("palette")) {
    const double k = number(at, "palette", n.value());
    if (k < 0 || k != std::floor(k) || k > 1e6)
      at.fail("palette", "a palette number is needed", n.value());
    pal.source = PaletteSource::library;
    pal.index = static_cast<int>(k);
    pal.colours = library_palette(options.palette_file, pal.index, pal.hue);
  } else {
    at.fail("palette", "a palette is needed (<palette>, <color> or palette=\"N\")");
  }
  return pal;
}

}  // namespace ifsfx::flame::detail

namespace ifsfx::flame {

std::array<Rgba, 256> library_palette(const std::string& palette_file, int number, double hue) {
  std::ifstream in(palette_file, std::ios::binary);
  if (!in)
    throw Error(ErrorKind::not_found,
                fmt::format("{}: flam3's palette library is needed for palette {} (Debian: "
                            "flam3-palette) (got no such file)",
                            palette_file, number));
  std::stringstream text;
  text << in.rdbuf();
  pugi::xml_document doc;
  const std::string s = text.str();
  if (!doc.load_buffer(s.data(), s.size()))
    throw Error(ErrorKind::parse, fmt::format("{}: not flam3's palette library (got a file that "
                                              "is not XML)",
                                              palette_file));
  const std::string key = std::to_string(number);
  for (const pugi::xml_node p : doc.child("palettes").children("palette")) {
    if (key != p.attribute("number").value()) continue;
    const auto c = detail::decode(p.attribute("data").value(), 256, 8, true);
    if (!c)
      throw Error(ErrorKind::parse, fmt::format("{}: palette {}: 256 colours of 8 hex digits "
                                                "are needed",
                                                palette_file, number));
    std::array<Rgba, 256> out = detail::first_256(*c);
    if (hue != 0)
      for (Rgba& e : out) e = detail::rotate_hue(e, hue);
    return out;
  }
  throw Error(ErrorKind::not_found,
              fmt::format("{}: no palette {} in flam3's palette library", palette_file, number));
}

}  // namespace ifsfx::flame
