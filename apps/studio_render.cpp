// SPDX-License-Identifier: Apache-2.0
#include "apps/studio_render.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "apps/cli_options.h"
#include "apps/render_metadata.h"
#include "apps/steal_modes.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"

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

std::string hex_colour(const Rgb& c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

}  // namespace

IfsPreset preset_from_json(const json& body) {
  if (!body.is_object()) bad_field("request", "must be a JSON object", body.type_name());
  Ifs ifs;
  ifs.name = text(body, "name", "studio");
  if (ifs.name.empty()) ifs.name = "studio";
  const std::string description = text(body, "description", "");
  if (!body.contains("maps") || !body["maps"].is_array() || body["maps"].empty())
    bad_field("maps", "must be a non-empty list of [a, b, c, d, e, f]",
              body.contains("maps") ? body["maps"].dump() : "nothing");
  if (body["maps"].size() > 64)
    bad_field("maps", "at most 64", std::to_string(body["maps"].size()));
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
  // Through the TOML text, as `ifsfx render` reads a saved preset: the same Ifs, the same text.
  IfsPreset preset = parse_ifs_toml(to_toml(ifs, description), ifs.name + ".toml");
  const bool allow_expansive = body.value("allow_expansive", false);
  validate(preset.ifs, preset.ifs.name, {.allow_expansive = allow_expansive});
  return preset;
}

json preset_to_json(const IfsPreset& preset) {
  json maps = json::array();
  for (const auto& m : preset.ifs.maps) maps.push_back({m.a, m.b, m.c, m.d, m.e, m.f});
  json colours = json::array();
  for (const auto& c : preset.ifs.colours) colours.push_back(hex_colour(c));
  return {{"name", preset.ifs.name},
          {"description", preset.description},
          {"maps", maps},
          {"probabilities", preset.ifs.probabilities},
          {"colours", colours}};
}

StudioRender studio_render_from_json(
    const json& body, const std::function<std::filesystem::path(const std::string&)>& source_path) {
  StudioRender r;
  r.preset = preset_from_json(body);
  r.size = size_option(text(body, "size", "768x768"), "size");
  if (r.size.width > 4096 || r.size.height > 4096)
    bad_field("size", "at most 4096x4096 in the studio", text(body, "size", ""));
  r.mode = text(body, "mode", "tops");
  if (r.mode != "attractor" && r.mode != "measure" && r.mode != "tops" && r.mode != "steal")
    throw Error(ErrorKind::invalid_argument,
                fmt::format("mode: attractor, measure, tops or steal (got {})", r.mode));
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
  }
  r.options.sampling.view = view_option(text(body, "view", ""), "view");
  if (body.contains("exact")) {
    if (!body["exact"].is_boolean())
      bad_field("exact", "must be true or false", body["exact"].dump());
    r.exact = body["exact"].get<bool>();
  }
  if (r.mode == "steal") r.source = source_path(text(body, "source", "sample"));
  return r;
}

StudioPicture render_png(const StudioRender& r, CancelToken cancel,
                         const std::filesystem::path& scratch) {
  RenderOptions options = r.options;
  options.sampling.cancel = cancel;
  const std::string output = (scratch / "render.png").string();  // the format of the picture
  const Rgb background = colour_option("black");
  RenderStats stats;
  cv::Mat image;
  std::vector<OutputFile> staged;
  if (r.mode == "attractor") {
    image = render_attractor(r.preset.ifs, r.size, options, &stats);
  } else if (r.mode == "measure") {
    image = render_measure(r.preset.ifs, r.size, options, &stats);
  } else if (r.mode == "tops") {
    image = tops_image(r.preset.ifs, r.size, {.sampling = options.sampling, .exact = r.exact},
                       background, output, &stats);
  } else {
    image = steal_image(r.preset.ifs, r.size, {.sampling = options.sampling, .exact = r.exact},
                        {.source = r.source.string(),
                         .background = background,
                         .quiet = true,
                         .output = {.cancel = cancel}},
                        output, staged, &stats);
  }
  WriteOptions write;
  write.metadata = render_metadata(r.preset, r.mode, options.sampling.seed, stats.view);
  // Written under the output policy's temporary name and read back, never committed: the
  // destructor removes it.
  OutputFile file(output, {.cancel = cancel});
  write_image(file, image, write);
  std::ifstream in(file.temporary(), std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.good() && !in.eof())
    throw Error(ErrorKind::io, fmt::format("{}: cannot read back", file.temporary().string()));
  return {std::move(bytes), stats.view};
}

}  // namespace ifsfx::app
