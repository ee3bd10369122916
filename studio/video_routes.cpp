// SPDX-License-Identifier: Apache-2.0
// Video (docs/studio.md, studio/video.h): the folder's movies (and --source's), a movie's size
// and length, a frame of it through the fractal filter, the camera's newest frame likewise, and
// the camera closed when the page leaves it.
#include <cstdint>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ifs/error.h"
#include "studio/fields.h"
#include "studio/folder.h"
#include "studio/http.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

json movies(const StudioContext& context) {
  json list = json::array();
  if (context.has_source_movie()) list.push_back(StudioContext::kSourceName);
  for (const auto& name : folder_files(context.folder(), movie_extensions())) list.push_back(name);
  return list;
}

void movie_frame(const httplib::Request& req, httplib::Response& res, StudioState& studio) {
  const json body = json_body(req);
  const auto movie = studio.context.movie_path(required_text(body, "movie"));
  const std::int64_t index = integer_field(body, "frame", 0, 0, 1LL << 40);
  const std::string client = client_of(req);
  double fps = 25;
  const cv::Mat frame = studio.movies.frame(client, movie, index, fps);
  res.set_header("X-Ifsfx-Frame", std::to_string(index));
  res.set_content(studio.previews.jpeg("movie/" + client, body, frame, index, -1, fps),
                  "image/jpeg");
}

void camera_frame(const httplib::Request& req, httplib::Response& res, StudioState& studio) {
  if (!studio.camera)
    throw Error(ErrorKind::not_found, "camera: none (start the studio with --camera /dev/videoN)");
  const json body = json_body(req);
  const std::string client = client_of(req);
  double seconds = 0;
  const cv::Mat frame = studio.camera->frame(seconds);
  res.set_header("X-Ifsfx-Seconds", fmt::format("{:.3f}", seconds));
  res.set_content(studio.previews.jpeg("camera/" + client, body, frame, 0, seconds, 30),
                  "image/jpeg");
}

}  // namespace

void add_video_routes(httplib::Server& server, StudioState& studio) {
  server.Get("/api/movies", guard([&studio](const httplib::Request&, httplib::Response& res) {
               send_json(res, movies(studio.context));
             }));
  server.Get("/api/video/info",
             guard([&studio](const httplib::Request& req, httplib::Response& res) {
               const std::string name = req.get_param_value("movie");
               send_json(res, MovieFrames::info(studio.context.movie_path(name), name));
             }));
  server.Post("/api/video/frame",
              guard([&studio](const httplib::Request& req, httplib::Response& res) {
                movie_frame(req, res, studio);
              }));
  server.Post("/api/camera/frame",
              guard([&studio](const httplib::Request& req, httplib::Response& res) {
                camera_frame(req, res, studio);
              }));
  server.Post(
      "/api/camera/stop", guard([&studio](const httplib::Request&, httplib::Response& res) {
        if (studio.camera) studio.camera->close();
        send_json(res, {{"closed", studio.camera ? json(studio.camera->device()) : json(nullptr)}});
      }));
}

}  // namespace ifsfx::app
