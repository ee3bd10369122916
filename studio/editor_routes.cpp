// SPDX-License-Identifier: Apache-2.0
// The editor's routes (docs/studio.md, "The API"): the shipped presets and those of the folder, a
// preset opened, the defaults for N maps, a render of the page's whole preset, and save.
#include <chrono>
#include <cstddef>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ifs/error.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "studio/flame_doc.h"
#include "studio/folder.h"
#include "studio/http.h"
#include "studio/render.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A positive whole number query parameter no larger than `most`.
int count_param(const httplib::Request& req, const char* name, int most) {
  const std::string text = req.get_param_value(name);
  static const std::regex digits("[0-9]{1,6}");
  const int value = std::regex_match(text, digits) ? std::stoi(text) : 0;
  if (value < 1 || value > most)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: a whole number from 1 to {} (got '{}')", name, most, text));
  return value;
}

json shipped_presets() {
  json list = json::array();
  for (const auto& p : list_shipped_presets())
    if (p.problem.empty())
      list.push_back({{"name", p.name},
                      {"maps", p.maps},
                      {"contraction", p.contraction},
                      {"description", p.description}});
  return list;
}

// NAME.colouring.toml beside a folder preset NAME.toml, as the preset's "colouring" when it has
// as many maps (an input then, as the preset); a warning in the preset otherwise.
void attach_colouring(json& body, const fs::path& folder, const std::string& file, const Ifs& F) {
  const std::string cname = colouring_file_name(file);
  std::error_code ec;
  if (!fs::exists(folder / cname, ec)) return;
  try {
    const IfsPreset g =
        load_ifs(folder_file(folder, cname, true).string(), {.allow_expansive = true});
    if (g.ifs.size() != F.size())
      throw Error(ErrorKind::invalid_ifs, fmt::format("{}: one map per map of {} (got {} for {})",
                                                      cname, file, g.ifs.size(), F.size()));
    body["colouring"] = maps_to_json(g.ifs);
    body["origin_colouring"] = cname;
  } catch (const Error& e) {
    body["warnings"].push_back(fmt::format("colouring not used: {}", e.what()));
  }
}

// A preset: shipped (name=), of the folder (file= and, for a Fractint or flame file, entry=), or,
// with neither, the one of the command line. A folder file becomes an input (never saved over);
// NAME.toml brings its colouring NAME.colouring.toml when there is one; a flame comes as its
// document (studio/flame_doc.h).
json open_preset(const httplib::Request& req, StudioState& studio) {
  const fs::path& folder = studio.context.folder();
  if (req.has_param("file") && is_flame_name(req.get_param_value("file"))) {
    const std::string file = req.get_param_value("file");
    json body = flame_to_json(open_folder_flame(folder, file, req.get_param_value("entry")));
    studio.context.add_input(folder_file(folder, file, true));
    body["origin_file"] = file;
    body["origin_entry"] = req.get_param_value("entry");
    return body;
  }
  if (req.has_param("file")) {
    const std::string file = req.get_param_value("file");
    const IfsPreset preset = open_folder_preset(folder, file, req.get_param_value("entry"));
    studio.context.add_input(folder_file(folder, file, true));
    json body = preset_to_json(preset);
    body["origin_file"] = file;
    if (preset.format == PresetFormat::fractint) body["origin_entry"] = preset.ifs.name;
    if (preset.format == PresetFormat::toml) attach_colouring(body, folder, file, preset.ifs);
    return body;
  }
  if (!req.has_param("name")) return preset_to_json(studio.initial);
  const std::string name = req.get_param_value("name");
  bool shipped = false;
  for (const auto& p : list_shipped_presets()) shipped |= p.name == name && p.problem.empty();
  if (!shipped)
    throw Error(ErrorKind::not_found, fmt::format("preset: not a shipped preset (got '{}')", name));
  return preset_to_json(load_ifs(name));
}

// What the page needs for N maps and the server computes: the default palette (the colours of
// tops and measure without "colours") and the default colouring IFS on the unit square.
json defaults(std::size_t n) {
  json colours = json::array();
  for (std::size_t i = 0; i < n; ++i) colours.push_back(hex_colour(palette_colour(i, n)));
  return {{"colours", colours}, {"colouring", maps_to_json(default_colouring(n))}};
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// The picture of the request's preset. A newer request of the same tab cancels this one (its
// render throws Error{interrupted}: 409).
void render(const httplib::Request& req, httplib::Response& res, StudioState& studio) {
  const auto received = std::chrono::steady_clock::now();
  check_body_size(req);
  const std::string client = client_of(req);
  const StudioRender render = studio_render_from_json(
      json::parse(req.body),
      [&studio](const std::string& n) { return studio.context.source_path(n); });
  const auto flag = studio.renders.start(client);
  std::optional<StudioPicture> picture;
  try {
    picture = render_picture(render, CancelToken(flag.get()));
  } catch (...) {
    studio.renders.finish(client, flag);
    throw;
  }
  studio.renders.finish(client, flag);
  const Box& v = picture->view;
  res.set_header("X-Ifsfx-View", fmt::format("{},{},{},{}", v.x0, v.y0, v.x1, v.y1));
  res.set_header("X-Ifsfx-Size", fmt::format("{}x{}", render.size.width, render.size.height));
  res.set_header("X-Ifsfx-Render-Ms", fmt::format("{:.1f}", picture->render_ms));
  res.set_header("X-Ifsfx-Encode-Ms", fmt::format("{:.1f}", picture->encode_ms));
  res.set_header("X-Ifsfx-Request-Ms", fmt::format("{:.1f}", ms_since(received)));
  if (render.colouring) res.set_header("X-Ifsfx-Colouring", maps_to_json(*render.colouring).dump());
  res.set_content(std::move(picture->bytes),
                  render.format == PictureFormat::png ? "image/png" : "application/octet-stream");
}

// Saves a flame's document as flame XML, NAME.flame, in --folder under the output policy
// (a temporary name, then a rename): the file flam3-render and `ifsfx render` read.
json save_flame(const json& body, const StudioContext& context) {
  const std::string name = body.value("file", "");
  if (!is_flame_name(name) || name.size() < 7)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a flame is saved as NAME.flame (got '{}')", name));
  const StudioFlame flame = flame_from_json(body);
  write_file(folder_file(context.folder(), name, false), flame.xml, {.inputs = context.inputs()});
  return {{"saved", name}};
}

// Saves the request's preset as TOML in --folder under the output policy, and its colouring
// (when the request has one) as NAME.colouring.toml beside it, both or neither; a flame as
// save_flame does.
json save(const json& body, const StudioContext& context) {
  if (body.is_object() && body.contains("flame") && !body["flame"].is_null())
    return save_flame(body, context);
  const IfsPreset preset = preset_from_json(body);
  std::string name = body.value("file", "");
  if (name.size() < 6 || name.substr(name.size() - 5) != ".toml")
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a name ending in .toml (got '{}')", name));
  const OutputOptions policy{.inputs = context.inputs()};
  std::vector<OutputFile> files;
  files.emplace_back(folder_file(context.folder(), name, false), policy);
  write_file(files.back(), preset.text);
  json answer{{"saved", name}};
  const std::string cname = colouring_file_name(name);
  const std::string stem = name.substr(0, name.size() - 5);
  if (const auto g = colouring_preset(body, stem + "-colouring")) {
    colouring_from_json(body, preset.ifs);  // the count and the fit checked as a render would
    files.emplace_back(folder_file(context.folder(), cname, false), policy);
    write_file(files.back(), g->text);
    answer["colouring"] = cname;
  }
  commit_together(files);
  return answer;
}

}  // namespace

void add_editor_routes(httplib::Server& server, StudioState& studio) {
  server.Get("/api/presets", guard([](const httplib::Request&, httplib::Response& res) {
               send_json(res, shipped_presets());
             }));
  server.Get("/api/preset", guard([&studio](const httplib::Request& req, httplib::Response& res) {
               send_json(res, open_preset(req, studio));
             }));
  server.Get("/api/folder", guard([&studio](const httplib::Request&, httplib::Response& res) {
               send_json(res, folder_presets(studio.context.folder()));
             }));
  server.Get("/api/flame/variations", guard([](const httplib::Request&, httplib::Response& res) {
               send_json(res, variations_json());
             }));
  server.Get("/api/defaults", guard([](const httplib::Request& req, httplib::Response& res) {
               send_json(res, defaults(static_cast<std::size_t>(
                                  count_param(req, "maps", static_cast<int>(kMaxMaps)))));
             }));
  server.Post("/api/render", guard([&studio](const httplib::Request& req, httplib::Response& res) {
                render(req, res, studio);
              }));
  server.Post("/api/save", guard([&studio](const httplib::Request& req, httplib::Response& res) {
                send_json(res, save(json_body(req), studio.context));
              }));
}

}  // namespace ifsfx::app
