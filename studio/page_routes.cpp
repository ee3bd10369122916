// SPDX-License-Identifier: Apache-2.0
// The page: index.html (which sets the token's cookie from the URL), its scripts, styles and the
// sample source, and the session the page asks for at start (--source, --camera, the upload
// limit).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "studio/folder.h"
#include "studio/gate.h"
#include "studio/http.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

json session(const StudioState& studio) {
  const StudioContext& c = studio.context;
  json source = nullptr;
  if (!c.source().empty())
    source = {{"name", StudioContext::kSourceName},
              {"file", c.source().filename().string()},
              {"kind", c.source_is_movie() ? "movie" : "image"}};
  return {{"source", source},
          {"camera", studio.camera ? json(studio.camera->device()) : json(nullptr)},
          {"upload_limit", kMaxUploadBytes}};
}

}  // namespace

void add_page_routes(httplib::Server& server, StudioState& studio) {
  server.Get(
      "/", guard([&studio](const httplib::Request& req, httplib::Response& res) {
        if (req.has_param("token") && same_secret(req.get_param_value("token"), studio.token))
          res.set_header("Set-Cookie", fmt::format("{}={}; Path=/; HttpOnly; SameSite=Strict",
                                                   kTokenCookie, studio.token));
        res.set_header("Content-Security-Policy",
                       "default-src 'self'; img-src 'self' blob: data:; connect-src 'self'");
        res.set_content(read_whole(studio.context.web() / "index.html"),
                        "text/html; charset=utf-8");
      }));
  // The page's other files (its ES modules, styles and the sample source): plain names of the
  // web folder only.
  server.Get(R"(/([a-z][a-z0-9_-]*)\.(js|css|png))",
             guard([&studio](const httplib::Request& req, httplib::Response& res) {
               const std::string ext = req.matches[2].str();
               const fs::path path = studio.context.web() / (req.matches[1].str() + "." + ext);
               std::error_code ec;
               if (!fs::is_regular_file(path, ec)) {
                 send_error(res, 404, fmt::format("{}: no such file", req.path));
                 return;
               }
               res.set_content(read_whole(path), ext == "js"    ? "text/javascript"
                                                 : ext == "css" ? "text/css"
                                                                : "image/png");
             }));
  server.Get("/api/session", guard([&studio](const httplib::Request&, httplib::Response& res) {
               send_json(res, session(studio));
             }));
}

}  // namespace ifsfx::app
