// SPDX-License-Identifier: Apache-2.0
// SuperIFSs (docs/studio.md, studio/superifs.h): the shipped ones and the folder's
// *.super.toml, one opened, one saved, and the textures of its V-variable sequence step by step.
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ifs/error.h"
#include "ifs/output_file.h"
#include "studio/fields.h"
#include "studio/folder.h"
#include "studio/http.h"
#include "studio/routes.h"
#include "superifs/superifs_file.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

json superifs_list(const StudioContext& context) {
  json shipped = json::array();
  for (const auto& s : list_shipped_superifs())
    shipped.push_back(
        {{"name", s.name}, {"ifs", s.ifs}, {"maps", s.maps}, {"description", s.description}});
  json files = json::array();
  for (const auto& name : folder_files(context.folder(), {".toml"}))
    if (name.ends_with(superifs_extension)) files.push_back(name);
  return {{"shipped", shipped}, {"files", files}};
}

json open_superifs(const httplib::Request& req, const StudioContext& context) {
  if (req.has_param("file"))
    return superifs_to_json(
        load_superifs(folder_file(context.folder(), req.get_param_value("file"), true).string()));
  const std::string name = req.get_param_value("name");
  bool shipped = false;
  for (const auto& s : list_shipped_superifs()) shipped |= s.name == name;
  if (!shipped)
    throw Error(ErrorKind::not_found,
                fmt::format("superifs: not a shipped superIFS (got '{}')", name));
  return superifs_to_json(load_superifs(name));
}

json save_superifs(const json& body, const StudioContext& context) {
  if (!body.is_object() || !body.contains("superifs"))
    throw Error(ErrorKind::parse, "superifs: must be given (got nothing)");
  const SuperIfsPreset preset = superifs_from_json(body["superifs"]);
  const std::string name = required_text(body, "file");
  if (!name.ends_with(superifs_extension))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("file: a name ending in {} (got '{}')", superifs_extension, name));
  write_file(folder_file(context.folder(), name, false), preset.text, {.inputs = context.inputs()});
  return {{"saved", name}};
}

}  // namespace

void add_superifs_routes(httplib::Server& server, StudioState& studio) {
  server.Get("/api/superifs", guard([&studio](const httplib::Request&, httplib::Response& res) {
               send_json(res, superifs_list(studio.context));
             }));
  server.Get("/api/superifs/preset",
             guard([&studio](const httplib::Request& req, httplib::Response& res) {
               send_json(res, open_superifs(req, studio.context));
             }));
  server.Post("/api/superifs/save",
              guard([&studio](const httplib::Request& req, httplib::Response& res) {
                send_json(res, save_superifs(json_body(req), studio.context));
              }));
  server.Post(
      "/api/texture/frame", guard([&studio](const httplib::Request& req, httplib::Response& res) {
        res.set_content(studio.textures.frame_png(json_body(req), client_of(req), studio.context),
                        "image/png");
      }));
}

}  // namespace ifsfx::app
