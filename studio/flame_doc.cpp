// SPDX-License-Identifier: Apache-2.0
#include "studio/flame_doc.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "flame/flame_file.h"
#include "flame/flame_write.h"
#include "flame/variations.h"
#include "ifs/error.h"
#include "studio/fields.h"
#include "studio/render.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;
namespace fl = ifsfx::flame;

// The editor plane: the flame plane turned by the camera's rotate (as flame/render_camera.h
// turns the plotted point) and flipped to y up. The map q = S·R(t)·p is a reflection, its own
// inverse, so it takes points and maps either way; with rotate 0 it only negates, exactly.
AffineMap editor_of(const fl::Camera& camera) {
  const double t = camera.rotate * std::numbers::pi / 180;
  const double c = std::cos(t), s = std::sin(t);
  return {c, -s, -s, -c, 0, 0};
}

// m seen through T (T ∘ m ∘ T): a flame-plane map in the editor plane, or back.
AffineMap conjugated(const AffineMap& m, const AffineMap& T) {
  return T.compose(m).compose(T);
}

// ---- to the page ----

json coefs_json(const AffineMap& m) {
  return fl::to_flam3_coefs(m);
}

json rgba_json(const fl::Rgba& c) {
  return {c.r, c.g, c.b, c.a};
}

json terms_json(const std::vector<fl::VariationTerm>& terms) {
  json list = json::array();
  for (const fl::VariationTerm& t : terms) {
    const fl::Variation& v = fl::variation(t.id);
    json params = json::object();
    for (std::size_t k = 0; k < t.params.size(); ++k)
      params[std::string(v.parameters[k].name)] = t.params[k];
    list.push_back({{"name", v.name}, {"weight", t.weight}, {"params", params}});
  }
  return list;
}

json xform_json(const fl::Xform& xf) {
  return {{"name", xf.name},
          {"weight", xf.weight},
          {"colour", xf.colour},
          {"colour_speed", xf.colour_speed},
          {"opacity", xf.opacity},
          {"chaos", xf.chaos},
          {"post", xf.post ? coefs_json(*xf.post) : json(nullptr)},
          {"variations", terms_json(xf.variations)},
          {"pre_variations", terms_json(xf.pre_variations)},
          {"post_variations", terms_json(xf.post_variations)}};
}

json settings_json(const fl::Flame& f) {
  const fl::Camera& c = f.camera;
  const fl::ToneMapping& t = f.tone;
  const fl::Filtering& s = f.filtering;
  json colours = json::array();
  for (const fl::Rgba& rgba : f.palette.colours) colours.push_back(rgba_json(rgba));
  const bool library = f.palette.source == fl::PaletteSource::library;
  return {{"camera",
           {{"size", {c.width, c.height}},
            {"center", {c.center.x, c.center.y}},
            {"scale", c.scale},
            {"zoom", c.zoom},
            {"rotate", c.rotate},
            {"zpos", c.zpos},
            {"perspective", c.perspective},
            {"yaw", c.yaw},
            {"pitch", c.pitch},
            {"depth_blur", c.depth_blur}}},
          {"palette",
           {{"colours", colours},
            {"source", library ? "library" : "inline"},
            {"index", f.palette.index},
            {"hue", f.palette.hue},
            {"mode", f.palette.mode == fl::PaletteMode::linear ? "linear" : "step"}}},
          {"tone",
           {{"brightness", t.brightness},
            {"gamma", t.gamma},
            {"gamma_threshold", t.gamma_threshold},
            {"vibrancy", t.vibrancy},
            {"highlight_power", t.highlight_power},
            {"contrast", t.contrast},
            {"background", rgba_json(t.background)}}},
          {"filtering",
           {{"supersample", s.supersample},
            {"filter_radius", s.filter_radius},
            {"filter_shape", s.filter_shape},
            {"estimator_radius", s.estimator_radius},
            {"estimator_minimum", s.estimator_minimum},
            {"estimator_curve", s.estimator_curve}}},
          {"quality", f.quality}};
}

// ---- from the page ----

// j[key] when present and not null.
const json* find(const json& j, const char* key, const std::string& path) {
  if (!j.is_object()) bad_field(path, "must be an object", j);
  const auto it = j.find(key);
  return it == j.end() || it->is_null() ? nullptr : &*it;
}

double as_number(const json& v, const std::string& path) {
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    bad_field(path, "must be a finite number", v);
  return v.get<double>();
}

// A list of finite numbers, of `count` (or, with `most`, from `count` to `most`) entries.
std::vector<double> numbers(const json& v, const std::string& path, std::size_t count,
                            std::size_t most = 0) {
  most = std::max(most, count);
  if (!v.is_array() || v.size() < count || v.size() > most)
    bad_field(path,
              count == most ? fmt::format("must be a list of {} numbers", count)
                            : fmt::format("must be a list of {} to {} numbers", count, most),
              v.is_array() ? json(fmt::format("{} entries", v.size())) : v);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(as_number(v[i], fmt::format("{}[{}]", path, i)));
  return out;
}

// The fields of `j` named in `fields`, each a finite number when present, into `out`.
template <typename T>
void read_numbers(const json& j, const std::string& path, T& out,
                  std::initializer_list<std::pair<const char*, double T::*>> fields) {
  for (const auto& [key, member] : fields)
    if (const json* v = find(j, key, path)) out.*member = as_number(*v, path + "." + key);
}

int whole(const json& j, const char* key, const std::string& path, int fallback, int low,
          int high) {
  const json* v = find(j, key, path);
  if (!v) return fallback;
  const double x = as_number(*v, path + "." + key);
  if (x != std::floor(x) || x < low || x > high)
    bad_field(path + "." + key, fmt::format("must be a whole number in [{}, {}]", low, high), *v);
  return static_cast<int>(x);
}

std::string text(const json& j, const char* key, const std::string& path,
                 const std::string& fallback) {
  const json* v = find(j, key, path);
  if (!v) return fallback;
  if (!v->is_string()) bad_field(path + "." + key, "must be a string", *v);
  return v->get<std::string>();
}

const json& list(const json& j, const char* key, const std::string& path) {
  const json* v = find(j, key, path);
  if (!v || !v->is_array()) bad_field(path + "." + key, "must be a list", v ? *v : json(nullptr));
  return *v;
}

fl::Rgba rgba(const json& v, const std::string& path) {
  const std::vector<double> c = numbers(v, path, 3, 4);
  return {c[0], c[1], c[2], c.size() == 4 ? c[3] : 1.0};
}

AffineMap coefs_of(const json& v, const std::string& path) {
  const std::vector<double> k = numbers(v, path, 6);
  return fl::from_flam3_coefs({k[0], k[1], k[2], k[3], k[4], k[5]});
}

fl::VariationTerm term_of(const json& j, const std::string& path) {
  const std::string name = text(j, "name", path, "");
  const fl::Variation* v = fl::find_variation(name);
  if (!v) bad_field(path + ".name", "a variation of GET /api/flame/variations", name);
  fl::VariationTerm t{.id = v->id, .params = fl::default_parameters(*v)};
  if (const json* w = find(j, "weight", path)) t.weight = as_number(*w, path + ".weight");
  const json* params = find(j, "params", path);
  if (!params) return t;
  if (!params->is_object()) bad_field(path + ".params", "must be an object", *params);
  for (auto it = params->begin(); it != params->end(); ++it) {
    const std::string& key = it.key();
    std::size_t k = 0;
    while (k < v->parameters.size() && v->parameters[k].name != key) ++k;
    if (k == v->parameters.size())
      bad_field(path + ".params", fmt::format("the parameters of {}", name), json(key));
    t.params[k] = as_number(it.value(), path + ".params." + key);
  }
  return t;
}

std::vector<fl::VariationTerm> terms_of(const json& xf, const char* key, const std::string& path) {
  std::vector<fl::VariationTerm> terms;
  if (!find(xf, key, path)) return terms;
  const json& items = list(xf, key, path);
  for (std::size_t i = 0; i < items.size(); ++i)
    terms.push_back(term_of(items[i], fmt::format("{}.{}[{}]", path, key, i)));
  return terms;
}

fl::Xform xform_of(const json& j, const std::string& path, bool is_final) {
  fl::Xform xf;
  xf.colour_speed = is_final ? 0.0 : 0.5;  // the reader's defaults
  xf.name = text(j, "name", path, "");
  read_numbers<fl::Xform>(j, path, xf,
                          {{"weight", &fl::Xform::weight},
                           {"colour", &fl::Xform::colour},
                           {"colour_speed", &fl::Xform::colour_speed},
                           {"opacity", &fl::Xform::opacity}});
  if (const json* c = find(j, "chaos", path)) xf.chaos = numbers(*c, path + ".chaos", 0, 1000);
  if (const json* p = find(j, "post", path)) xf.post = coefs_of(*p, path + ".post");
  xf.pre_variations = terms_of(j, "pre_variations", path);
  xf.variations = terms_of(j, "variations", path);
  xf.post_variations = terms_of(j, "post_variations", path);
  return xf;
}

void camera_of(const json& j, const std::string& path, fl::Camera& c) {
  if (const json* s = find(j, "size", path)) {
    const std::vector<double> wh = numbers(*s, path + ".size", 2);
    for (double x : wh)
      if (x != std::floor(x) || x < 1 || x > 65536)
        bad_field(path + ".size", "must be two whole numbers in [1, 65536]", *s);
    c.width = static_cast<int>(wh[0]);
    c.height = static_cast<int>(wh[1]);
  }
  if (const json* p = find(j, "center", path)) {
    const std::vector<double> xy = numbers(*p, path + ".center", 2);
    c.center = {xy[0], xy[1]};
  }
  read_numbers<fl::Camera>(j, path, c,
                           {{"scale", &fl::Camera::scale},
                            {"zoom", &fl::Camera::zoom},
                            {"rotate", &fl::Camera::rotate},
                            {"zpos", &fl::Camera::zpos},
                            {"perspective", &fl::Camera::perspective},
                            {"yaw", &fl::Camera::yaw},
                            {"pitch", &fl::Camera::pitch},
                            {"depth_blur", &fl::Camera::depth_blur}});
}

void palette_of(const json& j, const std::string& path, fl::Palette& p) {
  if (find(j, "colours", path)) {
    const json& colours = list(j, "colours", path);
    if (colours.size() != 256)
      bad_field(path + ".colours", "must be 256 colours",
                json(fmt::format("{} colours", colours.size())));
    for (std::size_t k = 0; k < 256; ++k)
      p.colours[k] = rgba(colours[k], fmt::format("{}.colours[{}]", path, k));
  }
  const std::string source = text(j, "source", path, "inline");
  if (source != "inline" && source != "library")
    bad_field(path + ".source", "inline or library", json(source));
  p.source = source == "library" ? fl::PaletteSource::library : fl::PaletteSource::inline_colours;
  p.index = whole(j, "index", path, -1, -1, 1000000);
  if (p.source == fl::PaletteSource::library && p.index < 0)
    bad_field(path + ".index", "a library palette's number", json(p.index));
  read_numbers<fl::Palette>(j, path, p, {{"hue", &fl::Palette::hue}});
  const std::string mode = text(j, "mode", path, "step");
  if (mode != "step" && mode != "linear") bad_field(path + ".mode", "step or linear", json(mode));
  p.mode = mode == "linear" ? fl::PaletteMode::linear : fl::PaletteMode::step;
}

void settings_of(const json& j, fl::Flame& f) {
  if (const json* c = find(j, "camera", "flame")) camera_of(*c, "flame.camera", f.camera);
  if (const json* p = find(j, "palette", "flame")) palette_of(*p, "flame.palette", f.palette);
  if (const json* t = find(j, "tone", "flame")) {
    using T = fl::ToneMapping;
    read_numbers<T>(*t, "flame.tone", f.tone,
                    {{"brightness", &T::brightness},
                     {"gamma", &T::gamma},
                     {"gamma_threshold", &T::gamma_threshold},
                     {"vibrancy", &T::vibrancy},
                     {"highlight_power", &T::highlight_power},
                     {"contrast", &T::contrast}});
    if (const json* b = find(*t, "background", "flame.tone"))
      f.tone.background = rgba(*b, "flame.tone.background");
  }
  if (const json* s = find(j, "filtering", "flame")) {
    using F = fl::Filtering;
    read_numbers<F>(*s, "flame.filtering", f.filtering,
                    {{"filter_radius", &F::filter_radius},
                     {"estimator_radius", &F::estimator_radius},
                     {"estimator_minimum", &F::estimator_minimum},
                     {"estimator_curve", &F::estimator_curve}});
    f.filtering.supersample = whole(*s, "supersample", "flame.filtering", 1, 1, 16);
    f.filtering.filter_shape = text(*s, "filter_shape", "flame.filtering", "gaussian");
  }
  read_numbers<fl::Flame>(j, "flame", f, {{"quality", &fl::Flame::quality}});
}

// Through the flame file's text, as `ifsfx render` reads a saved flame: the reader's checks and
// messages, and the flame that Save writes. A library palette is not looked up again (its file
// is large; the page sent the colours it gave): the check carries it inline, and the flame keeps
// its number and hue.
StudioFlame checked(const fl::Flame& f) {
  fl::Flame probe = f;
  probe.palette.source = fl::PaletteSource::inline_colours;
  std::vector<fl::Flame> read = fl::parse_flames(fl::flame_xml(probe), "flame");
  StudioFlame out{.flame = std::move(read.at(0))};
  if (f.palette.source == fl::PaletteSource::library) out.flame.palette = f.palette;
  out.xml = fl::flame_xml(out.flame);
  return out;
}

}  // namespace

json flame_to_json(const fl::Flame& f) {
  const AffineMap T = editor_of(f.camera);
  json maps = json::array(), xforms = json::array();
  for (const fl::Xform& xf : f.xforms) {
    const AffineMap m = conjugated(xf.pre, T);
    maps.push_back({m.a, m.b, m.c, m.d, m.e, m.f});
    xforms.push_back(xform_json(xf));
  }
  json final = nullptr;
  if (f.final_xform) {
    final = xform_json(*f.final_xform);
    final["coefs"] = coefs_json(f.final_xform->pre);
  }
  json flame = settings_json(f);
  flame["xforms"] = std::move(xforms);
  flame["final"] = std::move(final);
  return {{"name", f.name},
          {"description", ""},
          {"maps", std::move(maps)},
          {"flame", flame},
          {"warnings", json::array()}};
}

StudioFlame flame_from_json(const json& body) {
  const json* doc = find(body, "flame", "request");
  if (!doc) bad_field("flame", "must be given", json(nullptr));
  fl::Flame f;
  f.name = text(body, "name", "request", "");
  settings_of(*doc, f);  // the camera first: the editor plane turns with it
  const AffineMap T = editor_of(f.camera);
  const json& maps = list(body, "maps", "request");
  const json& xforms = list(*doc, "xforms", "flame");
  if (maps.empty() || maps.size() > kMaxMaps || xforms.size() != maps.size())
    bad_field("flame.xforms", fmt::format("one per map, 1 to {}", kMaxMaps),
              json(fmt::format("{} xforms for {} maps", xforms.size(), maps.size())));
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const std::vector<double> m = numbers(maps[i], fmt::format("maps[{}]", i), 6);
    fl::Xform xf = xform_of(xforms[i], fmt::format("flame.xforms[{}]", i), false);
    xf.pre = conjugated(AffineMap::from_coefficients({m[0], m[1], m[2], m[3], m[4], m[5]}), T);
    f.xforms.push_back(std::move(xf));
  }
  if (const json* final = find(*doc, "final", "flame")) {
    f.final_xform = xform_of(*final, "flame.final", true);
    const json* coefs = find(*final, "coefs", "flame.final");
    if (!coefs) bad_field("flame.final.coefs", "must be given", json(nullptr));
    f.final_xform->pre = coefs_of(*coefs, "flame.final.coefs");
  }
  return checked(f);
}

fl::Camera studio_camera(const fl::Camera& camera, cv::Size size, const std::optional<Box>& view) {
  fl::Camera c = camera;
  c.width = size.width;
  c.height = size.height;
  if (!view) {
    c.scale *= static_cast<double>(size.width) / camera.width;  // as render_flame resizes
    return c;
  }
  c.center = editor_of(camera)(Point{(view->x0 + view->x1) / 2, (view->y0 + view->y1) / 2});
  c.scale = size.width / view->width() / std::exp2(camera.zoom);
  return c;
}

Box camera_view(const fl::Camera& camera) {
  const Point q = editor_of(camera)(camera.center);
  const double ppu = camera.scale * std::exp2(camera.zoom);
  const double w = camera.width / (2 * ppu), h = camera.height / (2 * ppu);
  return {q.x - w, q.y - h, q.x + w, q.y + h};
}

json variations_json() {
  json out = json::array();
  for (const fl::Variation& v : fl::variations()) {
    json params = json::array();
    for (const fl::VariationParameter& p : v.parameters)
      params.push_back({{"name", p.name}, {"default", p.default_value}});
    out.push_back({{"name", v.name},
                   {"params", params},
                   {"pre_only", v.place == fl::VariationPlace::pre_only}});
  }
  return out;
}

}  // namespace ifsfx::app
