// SPDX-License-Identifier: Apache-2.0
#include "engine/drawing.h"

#include <cmath>

#include <fmt/format.h>

#include "flame/flame_chaos.h"
#include "flame/flame_file.h"
#include "ifs/error.h"
#include "ifs/preset.h"

namespace ifsfx::engine {

Drawing load_drawing(const std::string& spec, const ValidateOptions& options,
                     std::vector<std::string>* warnings) {
  if (flame::is_flame_spec(spec)) {
    flame::Flame f = flame::read_flame(spec);
    if (f.name.empty()) f.name = spec;
    return f;
  }
  IfsPreset F = load_ifs(spec, options);
  if (F.ifs.name.empty()) F.ifs.name = spec;
  if (warnings) warnings->insert(warnings->end(), F.warnings.begin(), F.warnings.end());
  return std::move(F.ifs);
}

Ifs colouring_for(const std::string& spec, const Drawing& F, const std::string& what) {
  if (const Ifs* ifs = std::get_if<Ifs>(&F)) return load_colouring(spec, *ifs, what);
  // load_colouring counts F's maps: a stand-in with one map per xform, under the flame's name.
  Ifs stand_in;
  stand_in.name = name_of(F);
  stand_in.maps.resize(map_count(F));
  return load_colouring(spec, stand_in, what);
}

std::size_t map_count(const Drawing& drawing) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) return f->xforms.size();
  return std::get<Ifs>(drawing).size();
}

const std::string& name_of(const Drawing& drawing) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) return f->name;
  return std::get<Ifs>(drawing).name;
}

void check_drawing(const Drawing& drawing) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) {
    if (f->xforms.empty())
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("flame \"{}\": has no xform (got 0)", f->name));
    return;
  }
  const Ifs& F = std::get<Ifs>(drawing);
  validate(F, F.name.empty() ? "drawing" : F.name, {.allow_expansive = true});
}

StealMap steal_map(const Drawing& drawing, const Ifs& G, cv::Size size,
                   const StealMapOptions& options, StealMapStats* stats) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) {
    StealMapOptions chaos = options;
    chaos.exact = false;
    return flame::flame_steal_map(*f, G, size, chaos, stats);
  }
  return compute_steal_map(std::get<Ifs>(drawing), G, size, options, stats);
}

cv::Mat tops_picture(const Drawing& drawing, cv::Size size, const TopsOptions& options,
                     const Rgb& background, bool alpha, TopsPictureStats* stats) {
  if (const auto* f = std::get_if<flame::Flame>(&drawing)) {
    TopsOptions chaos = options;
    chaos.exact = false;
    return flame::flame_tops(*f, size, chaos, background, alpha, stats);
  }
  return ifsfx::tops_picture(std::get<Ifs>(drawing), size, options, background, alpha, stats);
}

StealMapOptions with_fixed_view(const Drawing& drawing, cv::Size size, StealMapOptions options) {
  if (const auto* F = std::get_if<Ifs>(&drawing))
    options.sampling.view = framed_viewport(*F, size, options.sampling).view;
  return options;
}

Drawing drift(const Drawing& base, double t, const DriftOptions& options) {
  const auto* f = std::get_if<flame::Flame>(&base);
  if (!f) return drift(std::get<Ifs>(base), t, options);
  Ifs pre;
  for (const flame::Xform& xf : f->xforms) pre.maps.push_back(xf.pre);
  DriftOptions o = options;
  // A flame's pre-affine maps need not contract, so they have no attractor to size the
  // translations by: the camera's view does.
  o.extent = f->camera.width / (f->camera.scale * std::exp2(f->camera.zoom));
  const Ifs moved = drift(pre, t, o);
  flame::Flame out = *f;
  for (std::size_t n = 0; n < out.xforms.size(); ++n) out.xforms[n].pre = moved.maps[n];
  return out;
}

}  // namespace ifsfx::engine
