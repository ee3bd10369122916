// SPDX-License-Identifier: Apache-2.0
// Steal sources (docs/studio.md): the list the page's Source menu shows (the sample, --source
// when it is an image, the folder's images), a source's pixels shown beside the canvas, and an
// image dropped on the page saved in the folder.
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "studio/folder.h"
#include "studio/http.h"
#include "studio/render.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

using nlohmann::json;

constexpr double kSourcePreview = 1024;  // the source beside the canvas, pixels a side

json sources(const StudioContext& context) {
  json list = json::array({"sample"});
  if (context.has_source_image()) list.push_back(StudioContext::kSourceName);
  for (const auto& name : folder_sources(context.folder())) list.push_back(name);
  return list;
}

// A source image to show beside the canvas: RGBA rows, at most kSourcePreview pixels a side,
// with X-Ifsfx-Size (what is sent) and X-Ifsfx-Source-Size (the file's own).
void send_source(const httplib::Request& req, httplib::Response& res,
                 const StudioContext& context) {
  cv::Mat image;
  try {
    image = read_image(context.source_path(req.get_param_value("name"))).pixels;
  } catch (const Error& e) {
    // A file of the folder that is no readable image: the request's fault, not the server's.
    if (e.kind() != ErrorKind::io) throw;
    throw Error(ErrorKind::invalid_argument, e.what());
  }
  const double scale =
      std::min(1.0, kSourcePreview / static_cast<double>(std::max(image.cols, image.rows)));
  cv::Mat shown = image;
  if (scale < 1)
    cv::resize(image, shown,
               cv::Size(std::max(1, static_cast<int>(std::lround(image.cols * scale))),
                        std::max(1, static_cast<int>(std::lround(image.rows * scale)))),
               0, 0, cv::INTER_AREA);
  res.set_header("X-Ifsfx-Size", fmt::format("{}x{}", shown.cols, shown.rows));
  res.set_header("X-Ifsfx-Source-Size", fmt::format("{}x{}", image.cols, image.rows));
  res.set_content(rgba_bytes(shown), "application/octet-stream");
}

}  // namespace

void add_source_routes(httplib::Server& server, StudioState& studio) {
  server.Get("/api/sources", guard([&studio](const httplib::Request&, httplib::Response& res) {
               send_json(res, sources(studio.context));
             }));
  server.Get("/api/source", guard([&studio](const httplib::Request& req, httplib::Response& res) {
               send_source(req, res, studio.context);
             }));
  // An image dropped on the page (the body's bytes), saved in --folder as ?name=, or under a
  // free name beside it: answers {"saved": NAME}.
  server.Post("/api/upload", guard([&studio](const httplib::Request& req, httplib::Response& res) {
                std::lock_guard lock(studio.upload_mutex);
                const std::string saved =
                    save_upload(studio.context.folder(), req.get_param_value("name"), req.body,
                                studio.context.scratch());
                send_json(res, {{"saved", saved}});
              }));
}

}  // namespace ifsfx::app
