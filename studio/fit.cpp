// SPDX-License-Identifier: Apache-2.0
#include "studio/fit.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "collage/fit.h"
#include "collage/preview.h"
#include "ifs/error.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "run/fit_run.h"
#include "studio/fields.h"
#include "studio/http.h"
#include "studio/render.h"

namespace ifsfx::app {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The extension of an image file told by its first bytes; empty for none of the kinds read.
std::string image_extension(const std::string& bytes) {
  const auto starts = [&](std::string_view magic, std::size_t at = 0) {
    return bytes.size() >= at + magic.size() && bytes.compare(at, magic.size(), magic) == 0;
  };
  if (starts("\x89PNG\r\n\x1a\n")) return ".png";
  if (starts("\xff\xd8\xff")) return ".jpg";
  if (starts(std::string_view("II*\0", 4)) || starts(std::string_view("MM\0*", 4))) return ".tif";
  if (starts("BM")) return ".bmp";
  if (starts("GIF87a") || starts("GIF89a")) return ".gif";
  if (starts("RIFF") && starts("WEBP", 8)) return ".webp";
  return {};
}

struct FitRequest {
  FitArgs args;        // args.target: the file to read
  std::string name;    // the shape's name as the page knows it
  std::string source;  // the file's name in the folder, if it is one
  std::shared_ptr<ScratchFile> upload;
};

// The settings of a fit from the request's fields (JSON, or the query's strings turned into it).
void read_settings(const json& body, FitRequest& r) {
  r.args.maps = static_cast<int>(integer_field(body, "maps", 4, 1, 32));
  // 0: no time cap, as `ifsfx fit --max-seconds 0`: then the maps are the same on any machine.
  r.args.max_seconds = number_field(body, "seconds", 5, 0, 600);
  r.args.max_evaluations = integer_field(body, "evaluations", 250000, 2, 100000000);
  r.args.size = std::to_string(integer_field(body, "size", 128, 16, 512));
  r.args.seed = static_cast<std::uint64_t>(integer_field(body, "seed", 1, 0, 1LL << 53));
  r.args.init = choice_field(body, "init", "search", {"search", "moments"}) == "moments"
                    ? collage::Initialisation::moments
                    : collage::Initialisation::search;
  if (body.contains("threshold") && !body["threshold"].is_null())
    r.args.threshold = number_field(body, "threshold", 0.5, 0, 1);
  r.args.invert = bool_field(body, "invert", false);
  r.args.reseed_share = number_field(body, "reseed_share", r.args.reseed_share, 0, kMaxFitShare);
  r.args.grow_share = number_field(body, "grow_share", r.args.grow_share, 0, kMaxFitShare);
  r.args.threads = 0;
}

int submit(JobQueue& jobs, FitRequest request) {
  JobSpec spec{.kind = "fit", .title = request.name};
  if (!request.source.empty()) spec.reads.push_back(request.args.target);
  return jobs.submit(std::move(spec), [request = std::move(request)](JobContext& job) {
    job.progress(0, "reading", request.name);
    const cv::Mat raster = fit_raster(request.args);
    // The preset is named after the shape, as `ifsfx fit hand.png` names it "hand".
    FitArgs shown = request.args;
    shown.target = request.name;
    collage::FitOptions options = fit_options(shown, job.cancel());
    options.fine_target = fit_fine_raster(request.args);
    const double seconds = request.args.max_seconds;
    const auto evaluations = static_cast<double>(request.args.max_evaluations);
    options.progress = [&job, seconds, evaluations](const collage::FitProgress& p) {
      const double best = std::isfinite(p.best_iou) ? p.best_iou : 0;
      // The share of the budget spent: of the time, or of the evaluations when that ends first.
      const double done =
          std::max(seconds > 0 ? p.seconds / seconds : 0, p.evaluations / evaluations);
      job.progress(std::min(done, 0.99), collage::to_string(p.phase),
                   fmt::format("run {}, best IoU {:.3f}, {:.1f} s", p.run + 1, best, p.seconds));
      job.set_result({{"best_iou", best}, {"evaluations", p.evaluations}});
    };
    const collage::FitResult result = collage::fit(raster, options);
    // A cancelled job ends cancelled (the fit keeps its best so far for the command line).
    if (result.interrupted) throw Error(ErrorKind::interrupted, "fit: cancelled");
    const collage::CollageReport& r = result.report;
    const std::string text = to_toml(result.ifs, fit_summary(shown, result));
    const IfsPreset preset = parse_ifs_toml(text, result.ifs.name + ".toml");
    job.progress(0.99, "preview");
    std::vector<unsigned char> png;
    cv::imencode(".png",
                 collage::fit_preview(raster, result.ifs, {.quality = 256, .seed = shown.seed}),
                 png);
    job.set_preview({png.begin(), png.end()});
    job.set_result({{"preset", preset_to_json(preset)},
                    {"toml", text},
                    {"best_iou", r.iou},
                    {"iou", r.iou},
                    {"collage_iou", r.collage_iou},
                    {"fine_iou", r.fine_iou},
                    {"fine_size", r.fine_size},
                    {"contraction", r.contraction},
                    {"collage_distance", r.collage_distance},
                    {"runs", result.runs},
                    {"evaluations", result.evaluations},
                    {"seconds", result.seconds},
                    {"time_capped", result.time_capped}});
    job.progress(
        1, "done",
        fmt::format("IoU {:.3f}, s {:.3f}, {:.1f} s", r.iou, r.contraction, result.seconds));
  });
}

}  // namespace

int submit_upload_fit(JobQueue& jobs, const std::string& bytes,
                      const std::multimap<std::string, std::string>& settings,
                      StudioContext& context) {
  if (bytes.empty()) throw Error(ErrorKind::invalid_argument, "upload: an image (got no bytes)");
  const std::string ext = image_extension(bytes);
  if (ext.empty())
    throw RequestError(415, fmt::format("upload: a PNG, JPEG, TIFF, BMP, GIF or WebP image (got {} "
                                        "bytes of something else)",
                                        bytes.size()));
  // The query's strings as JSON numbers and booleans, read by the same rules as a JSON body.
  json body = json::object();
  for (const auto& [key, value] : settings) {
    if (key == "init" || key == "name") {
      body[key] = value;
    } else if (key == "invert") {
      body[key] = value == "1" || value == "true";
    } else {
      try {
        std::size_t used = 0;
        body[key] = std::stod(value, &used);
        if (used != value.size()) throw std::invalid_argument(value);
      } catch (const std::exception&) {
        throw Error(ErrorKind::parse, fmt::format("{}: must be a number (got '{}')", key, value));
      }
    }
  }
  FitRequest request;
  read_settings(body, request);
  request.name = text_field(body, "name", "shape");
  try {
    folder_file(context.folder(), request.name, false);  // a plain name, as a folder's file
  } catch (const Error&) {
    request.name = "shape";
  }
  request.upload = std::make_shared<ScratchFile>(context.scratch_name(ext));
  write_file(request.upload->path(), bytes);
  request.args.target = request.upload->path().string();
  return submit(jobs, std::move(request));
}

int submit_folder_fit(JobQueue& jobs, const json& body, StudioContext& context) {
  FitRequest request;
  read_settings(body, request);
  request.source = required_text(body, "file");
  request.name = request.source;
  request.args.target = folder_file(context.folder(), request.source, true).string();
  return submit(jobs, std::move(request));
}

}  // namespace ifsfx::app
