// SPDX-License-Identifier: Apache-2.0
#include "studio/routes.h"

#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "ifs/error.h"
#include "studio/fields.h"
#include "studio/fit.h"
#include "studio/http.h"
#include "studio/render_jobs.h"
#include "superifs/superifs_file.h"

namespace ifsfx::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kMovieExtensions{".mp4", ".mkv", ".mov",  ".avi", ".webm",
                                                ".m4v", ".mpg", ".mpeg", ".ogv", ".wmv"};

int job_number(const httplib::Request& req) {
  const std::string digits = req.matches[1].str();
  if (digits.size() > 9)
    throw Error(ErrorKind::not_found, fmt::format("job: no such job (got {})", digits));
  return std::stoi(digits);
}

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

}  // namespace

bool is_movie_name(const fs::path& name) {
  const std::string ext = lower_extension(name);
  return std::find(kMovieExtensions.begin(), kMovieExtensions.end(), ext) != kMovieExtensions.end();
}

StudioExtras::StudioExtras(StudioExtrasConfig config)
    : config_(std::move(config)), folder_(config_.folder) {
  if (!config_.source.empty()) {
    std::error_code ec;
    source_ = fs::canonical(config_.source, ec);
    if (ec || !fs::is_regular_file(source_))
      throw Error(ErrorKind::not_found, fmt::format("--source {}: no such file", config_.source));
    source_is_movie_ = is_movie_name(source_);
  }
  if (!config_.camera.empty()) {
    struct stat st {};
    if (stat(config_.camera.c_str(), &st) != 0 || !S_ISCHR(st.st_mode))
      throw Error(ErrorKind::not_found,
                  fmt::format("--camera {}: no such device (a V4L2 camera is /dev/videoN)",
                              config_.camera));
    camera_ = std::make_unique<CameraFeed>(config_.camera);
  }
  context_ = std::make_unique<StudioContext>(
      folder_, config_.scratch, [this] { return inputs(); }, config_.source_path,
      [this](const std::string& name) { return movie_path(name); });
}

StudioExtras::~StudioExtras() {
  stop();
}

InputFiles StudioExtras::inputs() const {
  InputFiles files = config_.inputs ? config_.inputs() : InputFiles{};
  if (!source_.empty()) files.add(source_);
  return files;
}

std::optional<fs::path> StudioExtras::source_image(const std::string& name) const {
  if (name == kSourceName && !source_.empty() && !source_is_movie_) return source_;
  return std::nullopt;
}

fs::path StudioExtras::movie_path(const std::string& name) const {
  if (name == kSourceName && !source_.empty() && source_is_movie_) return source_;
  const fs::path path = folder_file(folder_, name, true);
  if (!is_movie_name(path))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("movie: a movie file ({}) of --folder (got '{}')",
                            ".mp4, .mkv, .mov, .avi, .webm, ...", name));
  return path;
}

void StudioExtras::stop() {
  jobs_.stop_all();
  previews_.stop_all();
  textures_.stop_all();
}

json StudioExtras::session() const {
  json source = nullptr;
  if (!source_.empty())
    source = {{"name", kSourceName},
              {"file", source_.filename().string()},
              {"kind", source_is_movie_ ? "movie" : "image"}};
  return {{"source", source},
          {"camera", camera_ ? json(camera_->device()) : json(nullptr)},
          {"upload_limit", kMaxUploadBytes}};
}

void StudioExtras::add_routes(httplib::Server& server) {
  server.Get("/api/session", [this](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] { send_json(res, session()); });
  });

  // ---- files of the folder ----
  server.Get("/api/file", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const std::string name = req.get_param_value("name");
      const fs::path path = folder_file(folder_, name, true);
      const auto [type, shown] = file_type(path);
      const auto size = static_cast<std::size_t>(fs::file_size(path));
      // Never a page of this origin: no script, no plugin, whatever the file holds.
      res.set_header("Content-Security-Policy",
                     "default-src 'none'; img-src 'self'; "
                     "media-src 'self'; sandbox");
      if (!shown)
        res.set_header("Content-Disposition", fmt::format("attachment; filename=\"{}\"", name));
      res.set_content_provider(
          size, type.c_str(),
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
    });
  });

  // ---- render jobs ----
  server.Get("/api/jobs", [this](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] { send_json(res, {{"jobs", jobs_.list()}}); });
  });
  server.Post("/api/jobs", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const int id = submit_render_job(jobs_, json_body(req), *context_);
      send_json(res, jobs_.get(id), 202);
    });
  });
  server.Get(R"(/api/jobs/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] { send_json(res, jobs_.get(job_number(req))); });
  });
  server.Post(R"(/api/jobs/(\d+)/cancel)",
              [this](const httplib::Request& req, httplib::Response& res) {
                guarded(res, [&] {
                  const int id = job_number(req);
                  jobs_.cancel(id);
                  send_json(res, jobs_.get(id));
                });
              });
  server.Get(R"(/api/jobs/(\d+)/preview)",
             [this](const httplib::Request& req, httplib::Response& res) {
               guarded(res, [&] {
                 const int id = job_number(req);
                 const auto png = jobs_.preview(id);
                 if (!png)
                   throw Error(ErrorKind::not_found, fmt::format("job {}: no preview (yet)", id));
                 res.set_content(*png, "image/png");
               });
             });

  // ---- fit: an uploaded shape (the body) or an image of the folder (JSON) ----
  server.Post("/api/fit", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const bool is_json = req.get_header_value("Content-Type").rfind("application/json", 0) == 0;
      const int id = is_json ? submit_folder_fit(jobs_, json_body(req), *context_)
                             : submit_upload_fit(jobs_, req.body, req.params, *context_);
      send_json(res, jobs_.get(id), 202);
    });
  });

  // ---- video: movies of the folder, the camera ----
  server.Get("/api/movies", [this](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] {
      json list = json::array();
      if (!source_.empty() && source_is_movie_) list.push_back(kSourceName);
      for (const auto& name : folder_files(folder_, kMovieExtensions)) list.push_back(name);
      send_json(res, list);
    });
  });
  server.Get("/api/video/info", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const std::string name = req.get_param_value("movie");
      send_json(res, MovieFrames::info(movie_path(name), name));
    });
  });
  server.Post("/api/video/frame", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const json body = json_body(req);
      const fs::path movie = movie_path(required_text(body, "movie"));
      const std::int64_t index = integer_field(body, "frame", 0, 0, 1LL << 40);
      const std::string client = client_of(req);
      double fps = 25;
      const cv::Mat frame = movies_.frame(client, movie, index, fps);
      res.set_header("X-Ifsfx-Frame", std::to_string(index));
      res.set_content(previews_.jpeg("movie/" + client, body, frame, index, -1, fps), "image/jpeg");
    });
  });
  server.Post("/api/camera/frame", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      if (!camera_)
        throw Error(ErrorKind::not_found,
                    "camera: none (start the studio with --camera /dev/videoN)");
      const json body = json_body(req);
      const std::string client = client_of(req);
      double seconds = 0;
      const cv::Mat frame = camera_->frame(seconds);
      res.set_header("X-Ifsfx-Seconds", fmt::format("{:.3f}", seconds));
      res.set_content(previews_.jpeg("camera/" + client, body, frame, 0, seconds, 30),
                      "image/jpeg");
    });
  });
  server.Post("/api/camera/stop", [this](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] {
      if (camera_) camera_->close();
      send_json(res, {{"closed", camera_ ? json(camera_->device()) : json(nullptr)}});
    });
  });

  // ---- superIFS ----
  server.Get("/api/superifs", [this](const httplib::Request&, httplib::Response& res) {
    guarded(res, [&] {
      json shipped = json::array();
      for (const auto& s : list_shipped_superifs())
        shipped.push_back(
            {{"name", s.name}, {"ifs", s.ifs}, {"maps", s.maps}, {"description", s.description}});
      json files = json::array();
      for (const auto& name : folder_files(folder_, {".toml"}))
        if (name.ends_with(superifs_extension)) files.push_back(name);
      send_json(res, {{"shipped", shipped}, {"files", files}});
    });
  });
  server.Get("/api/superifs/preset", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      if (req.has_param("file")) {
        send_json(res, superifs_to_json(load_superifs(
                           folder_file(folder_, req.get_param_value("file"), true).string())));
        return;
      }
      const std::string name = req.get_param_value("name");
      bool shipped = false;
      for (const auto& s : list_shipped_superifs()) shipped |= s.name == name;
      if (!shipped)
        throw Error(ErrorKind::not_found,
                    fmt::format("superifs: not a shipped superIFS (got '{}')", name));
      send_json(res, superifs_to_json(load_superifs(name)));
    });
  });
  server.Post("/api/superifs/save", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      const json body = json_body(req);
      if (!body.is_object() || !body.contains("superifs"))
        throw Error(ErrorKind::parse, "superifs: must be given (got nothing)");
      const SuperIfsPreset preset = superifs_from_json(body["superifs"]);
      const std::string name = required_text(body, "file");
      if (!name.ends_with(superifs_extension))
        throw Error(ErrorKind::invalid_argument,
                    fmt::format("file: a name ending in {} (got '{}')", superifs_extension, name));
      write_file(folder_file(folder_, name, false), preset.text, {.inputs = inputs()});
      send_json(res, {{"saved", name}});
    });
  });
  server.Post("/api/texture/frame", [this](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] {
      res.set_content(textures_.frame_png(json_body(req), client_of(req), *context_), "image/png");
    });
  });
}

}  // namespace ifsfx::app
