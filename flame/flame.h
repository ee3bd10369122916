// SPDX-License-Identifier: Apache-2.0
// A fractal flame (Draves & Reckase, "The Fractal Flame Algorithm", 2003/2008; docs/flames.md):
// xforms — an affine map followed by a weighted sum of non-linear variations, an optional post
// affine map and a colour coordinate — an optional final xform, a camera, a palette and the tone
// mapping of the log-density display. Everything a flame file says that changes the picture.
//
// Coordinates. The flame plane is flam3's plane, kept as it is: its y axis points DOWN in the
// picture (flam3 puts pixel row r at y = center.y + (r − H/2) / scale), while the IFS plane of
// ifsfx has y up (ifs/view.h). Variations are defined in the flame plane and are not symmetric
// under y ↦ −y, so the flame is never flipped; a renderer maps y downwards, and a writer of an
// ifsfx IFS conjugates its maps by the flip (flame/flame_write.h).
//
// Affine order. flam3 writes coefs="a b c d e f" meaning x' = a·x + c·y + e, y' = b·x + d·y + f
// (its matrix is stored by columns). An ifsfx::AffineMap is x' = a·x + b·y + e, y' = c·x + d·y + f,
// so the file's b and c swap: AffineMap{a, c, b, d, e, f} = from_flam3_coefs({a, b, c, d, e, f}).
// The paper's own tables use a third order, x' = a·x + b·y + c, y' = d·x + e·y + f; comments that
// quote it say so (flame/variations.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ifs/affine_map.h"

namespace ifsfx::flame {

// The flam3 coefficient order ("a b c d e f" of coefs= and post=) to and from ifsfx's order.
constexpr AffineMap from_flam3_coefs(const std::array<double, 6>& k) {
  return {k[0], k[2], k[1], k[3], k[4], k[5]};
}
constexpr std::array<double, 6> to_flam3_coefs(const AffineMap& m) {
  return {m.a, m.c, m.b, m.d, m.e, m.f};
}

// One term w·V(p) of an xform: a variation of the registry (flame/variations.h) with its weight
// and its parameter values.
struct VariationTerm {
  std::uint32_t id = 0;        // index into variations()
  double weight = 1;           // the variation's "amount" w
  std::vector<double> params;  // one per parameter of the variation, in the registry's order
  friend bool operator==(const VariationTerm&, const VariationTerm&) = default;
};

// One function of the flame (paper §3): p ← post(Σ_v w_v·V_v(pre(p))), with the pre_ variations
// applied in order to pre(p) before the sum and the post_ ones after it, before the post-affine
// map (flame/xform_eval.h), and the colour coordinate c ← (1 − s)·c + s·colour (paper §5).
struct Xform {
  std::string name;               // Apophysis/Fractorium's label; no effect on the picture
  AffineMap pre;                  // flame plane → flame plane, ifsfx order (see above)
  std::optional<AffineMap> post;  // none: the identity
  double weight = 1;              // relative probability of being picked (unused by the final)
  double colour = 0;              // the xform's colour, a palette coordinate in [0, 1]
  double colour_speed = 0.5;      // s; files' older `symmetry` σ is s = (1 − σ) / 2
  double opacity = 1;             // how much the points it makes are plotted, in [0, 1]
  // xaos: chaos[j] multiplies xform j's weight when the previous xform was this one. Missing
  // entries (and an empty row) are 1.
  std::vector<double> chaos;
  std::vector<VariationTerm> pre_variations;   // applied in order to the affine point, replacing it
  std::vector<VariationTerm> variations;       // summed; none: (0, 0), or pre_'s point if any
  std::vector<VariationTerm> post_variations;  // applied in order to the sum, then post
  friend bool operator==(const Xform&, const Xform&) = default;
};

// The view: which rectangle of the flame plane the picture shows.
struct Camera {
  int width = 512, height = 512;  // pixels
  Point center{0, 0};             // flame-plane point at the picture's centre
  double scale = 50;              // pixels per flame-plane unit at zoom 0
  double zoom = 0;                // scale × 2^zoom (flam3 raises the quality with it, × 4^zoom)
  double rotate = 0;              // degrees, about `center`
  // flam3 3.1's 3-D camera (points given a z by the 3-D variations); all 0 = the plane seen flat.
  double zpos = 0, perspective = 0, yaw = 0, pitch = 0, depth_blur = 0;
  friend bool operator==(const Camera&, const Camera&) = default;
};

struct Rgba {
  double r = 0, g = 0, b = 0, a = 1;  // each in [0, 1]
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

enum class PaletteSource {
  inline_colours,  // <palette> or <color> elements of the flame
  library,         // palette="N" of flam3-palettes.xml, hue-rotated by `hue`
};

// How a colour coordinate c ∈ [0, 1] reads the 256 entries.
enum class PaletteMode { step, linear };

struct Palette {
  std::array<Rgba, 256> colours{};
  PaletteSource source = PaletteSource::inline_colours;
  int index = -1;  // library palette number (source == library)
  double hue = 0;  // hue rotation in turns, applied to a library palette when it was read
  PaletteMode mode = PaletteMode::step;
  friend bool operator==(const Palette&, const Palette&) = default;
};

// The log-density display (paper §4) and its colour handling; flam3's names and defaults.
struct ToneMapping {
  double brightness = 4;
  double gamma = 4;
  double gamma_threshold = 0.01;
  double vibrancy = 1;
  double highlight_power = -1;  // < 0: flam3's original clipping
  double contrast = 1;
  // The empty plane: opaque unless the file says otherwise (a 4th number, JWildfire's
  // bg_transparency), as flam3-render draws it without its transparency option.
  Rgba background{0, 0, 0, 1};
  friend bool operator==(const ToneMapping&, const ToneMapping&) = default;
};

// Spatial antialiasing and density estimation (paper §6 and §8).
struct Filtering {
  int supersample = 1;         // histogram bins per pixel side (flam3's `oversample`)
  double filter_radius = 0.5;  // spatial filter radius, in pixels
  std::string filter_shape = "gaussian";
  double estimator_radius = 9;   // density estimation: the largest kernel radius, pixels
  double estimator_minimum = 0;  // … the smallest
  double estimator_curve = 0.4;  // radius = estimator_radius / count^curve
  friend bool operator==(const Filtering&, const Filtering&) = default;
};

struct Flame {
  std::string name;
  std::vector<Xform> xforms;
  std::optional<Xform> final_xform;  // applied to the plotted copy of each point only
  Camera camera;
  Palette palette;
  ToneMapping tone;
  Filtering filtering;
  double quality = 50;  // samples per pixel of the output (before zoom)
  friend bool operator==(const Flame&, const Flame&) = default;
};

}  // namespace ifsfx::flame
