// SPDX-License-Identifier: Apache-2.0
#include "studio/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "flame/flame_write.h"
#include "flame/render.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "ifs/parallel.h"
#include "ifs/steal_map.h"
#include "run/arguments.h"
#include "run/picture_options.h"
#include "run/render_metadata.h"
#include "run/render_still.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

[[noreturn]] void bad_field(const std::string& field, const std::string& rule,
                            const std::string& got) {
  throw Error(ErrorKind::parse, fmt::format("{}: {} (got {})", field, rule, got));
}

double number(const json& value, const std::string& field) {
  if (!value.is_number()) bad_field(field, "must be a number", value.dump());
  return value.get<double>();
}

std::string text(const json& body, const char* field, const std::string& fallback) {
  if (!body.contains(field)) return fallback;
  const json& value = body[field];
  if (!value.is_string()) bad_field(field, "must be a string", value.dump());
  return value.get<std::string>();
}

}  // namespace

IfsPreset preset_from_json(const json& body) {
  if (!body.is_object()) bad_field("request", "must be a JSON object", body.type_name());
  if (body.contains("flame") && !body["flame"].is_null())
    throw Error(ErrorKind::unsupported,
                fmt::format("flame: an affine IFS is needed here; a flame is rendered in the "
                            "editor and saved as .flame (got the flame '{}')",
                            text(body, "name", "")));
  Ifs ifs;
  ifs.name = text(body, "name", "studio");
  if (ifs.name.empty()) ifs.name = "studio";
  const std::string description = text(body, "description", "");
  if (!body.contains("maps") || !body["maps"].is_array() || body["maps"].empty())
    bad_field("maps", "must be a non-empty list of [a, b, c, d, e, f]",
              body.contains("maps") ? body["maps"].dump() : "nothing");
  if (body["maps"].size() > kMaxMaps)
    bad_field("maps", fmt::format("at most {}", kMaxMaps), std::to_string(body["maps"].size()));
  for (std::size_t i = 0; i < body["maps"].size(); ++i) {
    const json& m = body["maps"][i];
    const std::string field = fmt::format("maps[{}]", i);
    if (!m.is_array() || m.size() != 6) bad_field(field, "must be [a, b, c, d, e, f]", m.dump());
    ifs.maps.push_back({number(m[0], field), number(m[1], field), number(m[2], field),
                        number(m[3], field), number(m[4], field), number(m[5], field)});
  }
  if (body.contains("probabilities") && !body["probabilities"].is_null()) {
    const json& p = body["probabilities"];
    if (!p.is_array()) bad_field("probabilities", "must be a list of numbers", p.dump());
    for (const json& v : p) ifs.probabilities.push_back(number(v, "probabilities"));
  }
  if (body.contains("colours") && !body["colours"].is_null()) {
    const json& c = body["colours"];
    if (!c.is_array()) bad_field("colours", "must be a list of \"#rrggbb\"", c.dump());
    for (const json& v : c) {
      if (!v.is_string()) bad_field("colours", "must be a list of \"#rrggbb\"", v.dump());
      ifs.colours.push_back(colour_option(v.get<std::string>(), "colours"));
    }
  }
  bool allow_expansive = false;
  if (body.contains("allow_expansive")) {
    if (!body["allow_expansive"].is_boolean())
      bad_field("allow_expansive", "must be true or false", body["allow_expansive"].dump());
    allow_expansive = body["allow_expansive"].get<bool>();
  }
  // Through the TOML text, as `ifsfx render` reads a saved preset: the same Ifs, the same text
  // (with the key that lets the saved file load when its maps contract only on average).
  std::string text = to_toml(ifs, description);
  if (allow_expansive) text += "allow_expansive = true\n";
  IfsPreset preset = parse_ifs_toml(text, ifs.name + ".toml");
  validate(preset.ifs, preset.ifs.name, {.allow_expansive = allow_expansive});
  return preset;
}

std::string hex_colour(const Rgb& c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

json maps_to_json(const Ifs& ifs) {
  json maps = json::array();
  for (const auto& m : ifs.maps) maps.push_back({m.a, m.b, m.c, m.d, m.e, m.f});
  return maps;
}

json preset_to_json(const IfsPreset& preset) {
  const json maps = maps_to_json(preset.ifs);
  json colours = json::array();
  for (const auto& c : preset.ifs.colours) colours.push_back(hex_colour(c));
  // A Fractint entry that contracts only on average is accepted with a warning (load_ifs): the
  // page renders and saves it with allow_expansive.
  return {{"name", preset.ifs.name},
          {"description", preset.description},
          {"maps", maps},
          {"probabilities", preset.ifs.probabilities},
          {"colours", colours},
          {"allow_expansive", preset.allow_expansive || !preset.warnings.empty()},
          {"warnings", preset.warnings}};
}

std::optional<IfsPreset> colouring_preset(const json& body, const std::string& name) {
  if (!body.contains("colouring") || body["colouring"].is_null()) return std::nullopt;
  // Colouring tilings contract only over two steps (square-tiling-2/3): load_colouring accepts
  // them, so the TOML says so too.
  IfsPreset g = preset_from_json(
      json{{"name", name}, {"maps", body["colouring"]}, {"allow_expansive", true}});
  return g;
}

std::optional<Ifs> colouring_from_json(const json& body, const Ifs& F) {
  return colouring_from_json(body, F.size(), "map of the IFS");
}

std::optional<Ifs> colouring_from_json(const json& body, std::size_t maps, const std::string& per) {
  const auto g = colouring_preset(body, "colouring");
  if (!g) return std::nullopt;
  if (g->ifs.size() != maps)
    throw Error(ErrorKind::invalid_ifs,
                fmt::format("colouring: one map per {} (got {} for {})", per, g->ifs.size(), maps));
  return fit_to_unit_square(g->ifs);  // as load_colouring does with a --colouring preset
}

engine::Drawing drawing_from_json(const json& body, std::string* text) {
  if (body.is_object() && body.contains("flame") && !body["flame"].is_null()) {
    flame::Flame f = flame_from_json(body).flame;
    if (text) *text = flame::flame_xml(f);
    return f;
  }
  IfsPreset preset = preset_from_json(body);
  if (text) *text = preset.text;
  return std::move(preset.ifs);
}

std::optional<Ifs> colouring_for_drawing(const json& body, const engine::Drawing& drawing) {
  if (const auto* ifs = std::get_if<Ifs>(&drawing)) return colouring_from_json(body, *ifs);
  return colouring_from_json(body, engine::map_count(drawing), "xform of the flame");
}

StudioRender studio_render_from_json(
    const json& body, const std::function<std::filesystem::path(const std::string&)>& source_path) {
  StudioRender r;
  const bool flame = body.is_object() && body.contains("flame") && !body["flame"].is_null();
  if (flame)
    r.flame = flame_from_json(body);
  else
    r.preset = preset_from_json(body);
  r.size = size_option(text(body, "size", "768x768"), "size");
  if (r.size.width > 4096 || r.size.height > 4096)
    bad_field("size", "at most 4096x4096 in the studio", text(body, "size", ""));
  r.mode = parse_render_mode(text(body, "mode", flame ? "measure" : "tops"), "mode");
  if (flame) check_flame_mode(r.mode, "mode");
  // `ifsfx render`'s defaults (RenderOptions) but for the fields the page sets.
  if (body.contains("seed")) {
    const double seed = number(body["seed"], "seed");
    if (seed < 0 || seed != std::floor(seed) || seed > 9e15)
      bad_field("seed", "must be a whole number >= 0", body["seed"].dump());
    r.options.sampling.seed = static_cast<std::uint64_t>(seed);
  }
  if (body.contains("quality")) {
    r.options.sampling.quality = number(body["quality"], "quality");
    if (!(r.options.sampling.quality > 0 && r.options.sampling.quality <= kMaxQuality))
      bad_field("quality", fmt::format("must be in (0, {}]", kMaxQuality), body["quality"].dump());
    if (flame) r.flame->flame.quality = r.options.sampling.quality;
  }
  r.options.sampling.view = view_option(text(body, "view", ""), "view");
  if (body.contains("threads")) {
    // `ifsfx render --threads`: the same pixels for any count (docs/design.md §7).
    const double threads = number(body["threads"], "threads");
    if (threads < 0 || threads > kMaxThreads || threads != std::floor(threads))
      bad_field("threads", fmt::format("must be 0 (all cores) to {}", kMaxThreads),
                body["threads"].dump());
    r.options.sampling.threads = static_cast<int>(threads);
  }
  // A flame's tops and steal maps come from the chaos game unless the exact descent is asked for,
  // which render_still refuses with the reason (as `ifsfx render FILE.flame --exact`).
  if (flame) r.exact = false;
  if (body.contains("exact")) {
    if (!body["exact"].is_boolean())
      bad_field("exact", "must be true or false", body["exact"].dump());
    r.exact = body["exact"].get<bool>();
  }
  if (render_mode_info(r.mode).source) {
    r.source = source_path(text(body, "source", "sample"));
    r.colouring =
        flame ? colouring_from_json(body, r.flame->flame.xforms.size(), "xform of the flame")
              : colouring_from_json(body, r.preset.ifs);
  }
  const std::string format = text(body, "format", "png");
  if (format != "png" && format != "rgba") bad_field("format", "png or rgba", format);
  r.format = format == "rgba" ? PictureFormat::rgba : PictureFormat::png;
  return r;
}

std::string rgba_bytes(const cv::Mat& image) {
  cv::Mat pixels = image;
  if (pixels.depth() != CV_8U)  // as write_image converts for an 8-bit file (to_file_depth)
    image.convertTo(pixels, CV_8U, pixels.depth() == CV_16U ? 255.0 / 65535.0 : 255.0);
  cv::Mat rgba;
  const int code = pixels.channels() == 1   ? cv::COLOR_GRAY2RGBA
                   : pixels.channels() == 3 ? cv::COLOR_BGR2RGBA
                                            : cv::COLOR_BGRA2RGBA;
  cv::cvtColor(pixels, rgba, code);
  std::string bytes(rgba.total() * 4, '\0');
  cv::Mat view(rgba.size(), CV_8UC4, bytes.data());
  rgba.copyTo(view);
  return bytes;
}

namespace {

// The flame of a request as `ifsfx render FILE.flame --size WxH` renders it (the same call and
// options; the camera moved to the page's view when it has one), with the same metadata.
StudioImage flame_image(const StudioRender& r, CancelToken cancel, bool alpha) {
  flame::Flame f = r.flame->flame;
  f.camera = studio_camera(f.camera, r.size, r.options.sampling.view);
  const std::uint64_t seed = r.options.sampling.seed;
  const flame::FlameRenderOptions options{.seed = seed,
                                          .threads = r.options.sampling.threads,
                                          .cancel = cancel,
                                          .channels = alpha ? 4 : 3,
                                          .depth = r.flame_depth};
  StudioImage out{.image = flame::render_flame(f, options), .view = camera_view(f.camera)};
  out.write.metadata = flame_render_metadata(f.name, "measure", seed);
  return out;
}

// A flame's attractor, tops or steal picture as `ifsfx render FILE.flame --mode MODE --size WxH`
// makes it: its xforms through the chaos game, framed by its camera (moved to the page's view).
StudioImage flame_chaos_image(const StudioRender& r, StillJob job) {
  flame::Flame f = r.flame->flame;
  f.camera = studio_camera(f.camera, r.size, r.options.sampling.view);
  job.options.sampling.view.reset();  // the camera frames it
  StillResult still = render_still(engine::Drawing{f}, job);
  StudioImage out{.image = std::move(still.image), .view = camera_view(f.camera)};
  out.write.metadata = flame_render_metadata(f.name, to_string(r.mode), job.options.sampling.seed);
  return out;
}

}  // namespace

StudioImage studio_image(const StudioRender& r, CancelToken cancel, bool alpha) {
  if (r.flame && r.mode == RenderMode::measure) return flame_image(r, cancel, alpha);
  StillJob job{.mode = r.mode,
               .size = r.size,
               .options = r.options,
               .exact = r.exact,
               .background = colour_option("black"),
               .alpha = alpha,
               .colouring = r.colouring};
  job.options.sampling.cancel = cancel;
  if (render_mode_info(r.mode).source) job.source = read_image(r.source).pixels;
  if (r.flame) return flame_chaos_image(r, std::move(job));
  StillResult still = render_still(r.preset.ifs, job);
  StudioImage out{.image = std::move(still.image), .view = still.stats.view};
  out.write.metadata =
      render_metadata(r.preset, to_string(r.mode), job.options.sampling.seed, still.stats.view);
  return out;
}

StudioPicture render_picture(const StudioRender& r, CancelToken cancel) {
  using Clock = std::chrono::steady_clock;
  const auto ms_since = [](Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  };
  const auto start = Clock::now();
  const StudioImage image = studio_image(r, cancel, true);  // as a PNG keeps alpha
  StudioPicture picture{.view = image.view, .render_ms = ms_since(start)};
  const auto encode = Clock::now();
  picture.bytes = r.format == PictureFormat::rgba ? rgba_bytes(image.image)
                                                  : encode_image(image.image, ".png", image.write);
  picture.encode_ms = ms_since(encode);
  return picture;
}

}  // namespace ifsfx::app
