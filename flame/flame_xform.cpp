// SPDX-License-Identifier: Apache-2.0
// <xform> and <finalxform>: the affine maps, the colour, the xaos row and the variation terms.
// A variation is an attribute NAME="weight" (pre_NAME, post_NAME for the lists before and after
// the sum), its parameters NAME_PARAM (pre_NAME_PARAM, ...). Any other attribute that is not
// listed below as known is an unknown variation: refused, never dropped.
#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "flame/detail/flame_xml.h"
#include "flame/variations.h"

namespace ifsfx::flame::detail {
namespace {

// Attributes of an xform that are not variations: read below, or without effect on a still
// picture (animation, editor state, Ember's and JWildfire's extras that need their renderers).
bool known_attribute(std::string_view n) {
  static constexpr std::string_view kKnown[] = {"weight",
                                                "color",
                                                "color_speed",
                                                "symmetry",
                                                "opacity",
                                                "chaos",
                                                "coefs",
                                                "post",
                                                "name",
                                                "plotmode",
                                                "animate",
                                                "var_color",
                                                "motion_frequency",
                                                "motion_function",
                                                "motion_offset",
                                                "material",
                                                "material_speed",
                                                "mod_gamma",
                                                "mod_gamma_speed",
                                                "mod_contrast",
                                                "mod_contrast_speed",
                                                "mod_saturation",
                                                "mod_saturation_speed",
                                                "mod_hue",
                                                "mod_hue_speed",
                                                "color_type",
                                                "mirror_pre_post_translations",
                                                "yzCoefs",
                                                "zxCoefs",
                                                "yzPostCoefs",
                                                "zxPostCoefs"};
  return std::ranges::find(kKnown, n) != std::end(kKnown);
}

enum class List { pre, normal, post };

struct Found {
  const Variation* v;
  List list;
  std::string prefix;  // "", "pre_" or "post_": the prefix of its parameters' names too
  double weight;
};

// The variation an attribute names, with its list, or nothing.
std::optional<Found> variation_of(std::string_view n) {
  if (const Variation* v = find_variation(n))
    return Found{v, v->place == VariationPlace::pre_only ? List::pre : List::normal, "", 0};
  for (const auto& [prefix, list] :
       {std::pair{"pre_", List::pre}, std::pair{"post_", List::post}}) {
    const std::string_view p = prefix;
    if (n.starts_with(p)) {
      const Variation* v = find_variation(n.substr(p.size()));
      if (v && v->place == VariationPlace::any) return Found{v, list, std::string(p), 0};
    }
  }
  return std::nullopt;
}

// True when `n` (less a pre_/post_ prefix) is a parameter of some variation: a parameter whose
// variation is absent changes nothing, and some programs write them all.
bool parameter_of_any(std::string_view n) {
  for (std::string_view p : {"pre_", "post_"})
    if (n.starts_with(p) && parameter_of_any(n.substr(p.size()))) return true;
  for (const Variation& v : variations())
    for (const VariationParameter& q : v.parameters)
      if (q.name == n) return true;
  return false;
}

// JWildfire's motion curves: a value V (an xform's weightCurve, colorCurve, xyCoeff00Curve, …; a
// term's NAME_amountCurve; a parameter NAME_PARAM itself) may carry a curve over an animation's
// frames, written as V_enabled, V_view_xmin, …, V_point_count and the points V_x0, V_y0, …. The
// base V of such an attribute, or "" when `n` is not one.
std::string_view motion_curve_base(std::string_view n) {
  for (std::string_view suffix :
       {"_enabled", "_view_xmin", "_view_xmax", "_view_ymin", "_view_ymax", "_interpolation",
        "_selected_idx", "_locked", "_point_count"})
    if (n.ends_with(suffix)) return n.substr(0, n.size() - suffix.size());
  const std::size_t digits = n.find_last_not_of("0123456789");
  if (digits == std::string_view::npos || digits + 1 == n.size() || digits < 2) return {};
  if (n.substr(digits - 1, 2) != "_x" && n.substr(digits - 1, 2) != "_y") return {};
  return n.substr(0, digits - 1);
}

// True when `n` belongs to a motion curve of a value this xform has (a Curve of the xform or of a
// term, or a parameter read): a curve that is not enabled changes nothing in a still; an enabled
// one animates its value, which is refused rather than drawn at the static value.
bool disabled_motion_curve(const Where& at, const std::string& what, const pugi::xml_node& node,
                           std::string_view n, const std::set<std::string>& used) {
  const std::string_view base = motion_curve_base(n);
  if (base.empty() || !(base.ends_with("Curve") || used.contains(std::string(base)))) return false;
  const std::string enabled = std::string(base) + "_enabled";
  const std::string_view on = node.attribute(enabled.c_str()).value();
  if (!on.empty() && on != "false" && on != "0")
    at.fail(what + ": " + enabled,
            "a JWildfire motion curve animates this value over frames; ifsfx reads stills of "
            "flames without enabled curves",
            on);
  return true;
}

// JWildfire's affine maps of the yz and zx planes: the identity leaves a planar flame alone;
// any other moves points out of the plane (or into it from z), which a flame drawn in the plane
// cannot show, so it is refused rather than dropped.
void refuse_3d_affine(const Where& at, const std::string& what, const pugi::xml_node& node) {
  for (const char* name : {"yzCoefs", "zxCoefs", "yzPostCoefs", "zxPostCoefs"}) {
    const auto a = node.attribute(name);
    if (!a) continue;
    if (numbers(at, what + ": " + name, a.value(), 6) != std::vector<double>{1, 0, 0, 1, 0, 0})
      at.fail(what + ": " + name,
              "a 3-D affine map (JWildfire) moves points out of the plane; ifsfx draws flames in "
              "the plane, where only the identity leaves them",
              a.value());
  }
}

AffineMap affine(const Where& at, const std::string& what, const pugi::xml_attribute& a) {
  const std::vector<double> k = numbers(at, what + ": " + a.name(), a.value(), 6);
  return from_flam3_coefs({k[0], k[1], k[2], k[3], k[4], k[5]});
}

void read_colour(const Where& at, const std::string& what, const pugi::xml_node& node,
                 bool is_final, Xform& xf) {
  // color="c" (older files: "c1 c2", the second for a second palette: the first is used)
  if (const auto a = node.attribute("color")) {
    const std::vector<double> c = numbers(at, what + ": color", a.value());
    if (c.empty() || c.size() > 2) at.fail(what + ": color", "one number is needed", a.value());
    xf.colour = c[0];
  }
  // The final xform leaves the colour alone unless it says otherwise.
  xf.colour_speed = is_final ? 0.0 : 0.5;
  if (const auto a = node.attribute("symmetry"))
    xf.colour_speed = (1 - number(at, what + ": symmetry", a.value())) / 2;
  if (const auto a = node.attribute("color_speed"))
    xf.colour_speed = number(at, what + ": color_speed", a.value());
  xf.opacity = number_or(at, node, "opacity", 1);
  if (std::string_view(node.attribute("plotmode").value()) == "off") xf.opacity = 0;
}

// The message for attributes that are neither known, variations nor their parameters.
[[noreturn]] void refuse_unknown(const Where& at, const std::string& what,
                                 const std::vector<std::string>& unknown,
                                 const std::vector<Found>& found) {
  for (const std::string& u : unknown) {
    for (const Found& f : found) {
      const std::string var = f.prefix + std::string(f.v->name);
      if (u.starts_with(var + "_"))
        at.fail(what, fmt::format("unknown parameter \"{}\" of variation \"{}\"", u, var));
    }
  }
  // The shortest unknown name is the variation; longer ones are likely its parameters.
  const std::string& first =
      *std::min_element(unknown.begin(), unknown.end(),
                        [](const auto& a, const auto& b) { return a.size() < b.size(); });
  at.fail(what, fmt::format("unknown variation \"{}\"", first));
}

void read_variations(const Where& at, const std::string& what, const pugi::xml_node& node,
                     Xform& xf) {
  std::vector<Found> found;
  std::vector<std::string> rest;
  for (const pugi::xml_attribute a : node.attributes()) {
    const std::string_view n = a.name();
    // JWildfire's per-variation ordering hint (NAME_fx_priority) only orders what the lists
    // already order.
    if (known_attribute(n) || n.ends_with("_fx_priority")) continue;
    if (std::optional<Found> f = variation_of(n)) {
      for (const Found& g : found)
        if (g.v == f->v && g.list == f->list)
          at.fail(what + ": " + std::string(n), "a variation may be given once");
      f->weight = number(at, what + ": " + std::string(n), a.value());
      found.push_back(*f);
    } else {
      rest.emplace_back(n);
    }
  }
  std::set<std::string> used;
  for (const Found& f : found) {
    VariationTerm t{.id = f.v->id, .weight = f.weight, .params = default_parameters(*f.v)};
    for (std::size_t k = 0; k < f.v->parameters.size(); ++k) {
      const std::string name = f.prefix + std::string(f.v->parameters[k].name);
      if (const auto a = node.attribute(name.c_str())) {
        t.params[k] = number(at, what + ": " + name, a.value());
        used.insert(name);
      }
    }
    (f.list == List::pre    ? xf.pre_variations
     : f.list == List::post ? xf.post_variations
                            : xf.variations)
        .push_back(std::move(t));
  }
  std::vector<std::string> unknown;
  for (const std::string& n : rest)
    if (!used.contains(n) && !parameter_of_any(n) &&
        !disabled_motion_curve(at, what, node, n, used))
      unknown.push_back(n);
  if (!unknown.empty()) refuse_unknown(at, what, unknown, found);
}

}  // namespace

Xform parse_xform(const Where& at, const pugi::xml_node& node, const std::string& what,
                  bool is_final) {
  Xform xf;
  xf.name = node.attribute("name").value();
  const pugi::xml_attribute coefs = node.attribute("coefs");
  if (!coefs) at.fail(what + ": coefs", "the affine map is needed");
  xf.pre = affine(at, what, coefs);
  if (const auto post = node.attribute("post")) xf.post = affine(at, what, post);
  if (!is_final) {
    xf.weight = number_or(at, node, "weight", 1);
    if (xf.weight < 0) at.fail(what + ": weight", "must be >= 0", node.attribute("weight").value());
  }
  read_colour(at, what, node, is_final, xf);
  if (const auto chaos = node.attribute("chaos")) {
    xf.chaos = numbers(at, what + ": chaos", chaos.value());
    for (double c : xf.chaos)
      if (c < 0) at.fail(what + ": chaos", "xaos weights must be >= 0", chaos.value());
  }
  refuse_3d_affine(at, what, node);
  read_variations(at, what, node, xf);
  return xf;
}

}  // namespace ifsfx::flame::detail
