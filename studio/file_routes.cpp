// SPDX-License-Identifier: Apache-2.0
// A file of the folder (GET /api/file?name=NAME): media the page shows inline (a job's picture or
// movie), everything else as a download, read in pieces so that a large movie is never held
// whole.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "studio/folder.h"
#include "studio/http.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;

// How a file of the folder is served: media the page shows inline, everything else as a download
// (a page of the folder must never run as this server's page).
std::pair<std::string, bool> file_type(const fs::path& name) {
  const std::string ext = lower_extension(name);
  static const std::vector<std::pair<std::string, std::string>> inline_types{
      {".png", "image/png"},
      {".jpg", "image/jpeg"},
      {".jpeg", "image/jpeg"},
      {".webp", "image/webp"},
      {".gif", "image/gif"},
      {".bmp", "image/bmp"},
      {".mp4", "video/mp4"},
      {".m4v", "video/mp4"},
      {".webm", "video/webm"},
      {".mkv", "video/x-matroska"},
      {".mov", "video/quicktime"},
      {".toml", "text/plain; charset=utf-8"},
      {".ifs", "text/plain; charset=utf-8"}};
  for (const auto& [e, type] : inline_types)
    if (e == ext) return {type, true};
  return {"application/octet-stream", false};
}

void send_file(const httplib::Request& req, httplib::Response& res, const fs::path& folder) {
  const std::string name = req.get_param_value("name");
  const fs::path path = folder_file(folder, name, true);
  const auto [type, shown] = file_type(path);
  const auto size = static_cast<std::size_t>(fs::file_size(path));
  // Never a page of this origin: no script, no plugin, whatever the file holds.
  res.set_header("Content-Security-Policy",
                 "default-src 'none'; img-src 'self'; "
                 "media-src 'self'; sandbox");
  if (!shown)
    res.set_header("Content-Disposition", fmt::format("attachment; filename=\"{}\"", name));
  res.set_content_provider(size, type.c_str(),
                           [path](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             std::ifstream in(path, std::ios::binary);
                             in.seekg(static_cast<std::streamoff>(offset));
                             std::vector<char> buffer(std::min<std::size_t>(length, 1 << 16));
                             in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
                             const auto got = static_cast<std::size_t>(in.gcount());
                             if (got == 0) return false;
                             sink.write(buffer.data(), got);
                             return true;
                           });
}

}  // namespace

void add_file_routes(httplib::Server& server, StudioState& studio) {
  server.Get("/api/file", guard([&studio](const httplib::Request& req, httplib::Response& res) {
               send_file(req, res, studio.context.folder());
             }));
}

}  // namespace ifsfx::app
