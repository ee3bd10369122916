// SPDX-License-Identifier: Apache-2.0
// The studio's render jobs, fit, video, camera and superIFS (docs/studio.md, issue 24): their
// routes, registered on the studio's server by one call, and what they keep (the job queue, the
// tabs' decoders, engines and texture sequences). Every route is under /api/, behind the
// studio's token, Host and Origin checks; every file is named by a plain name of --folder.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <httplib.h>

#include "ifs/output_file.h"
#include "studio/context.h"
#include "studio/folder.h"
#include "studio/jobs.h"
#include "studio/superifs.h"
#include "studio/video.h"

namespace ifsfx::app {

struct StudioExtrasConfig {
  std::filesystem::path folder;        // --folder
  std::filesystem::path scratch;       // the studio's private temporary folder
  std::filesystem::path web;           // the page's files
  std::function<InputFiles()> inputs;  // files no output may replace (the presets opened)
  std::string source;                  // --source IMAGE|MOVIE, or ""
  std::string camera;                  // --camera /dev/videoN, or ""
  // Steal sources by the page's name ("sample", a file of the folder, "@source").
  std::function<std::filesystem::path(const std::string&)> source_path;
};

class StudioExtras {
 public:
  // The name of --source in the page.
  static constexpr const char* kSourceName = "@source";

  // Throws Error{not_found} naming --source or --camera when the file or device is missing.
  explicit StudioExtras(StudioExtrasConfig config);
  ~StudioExtras();  // stop(), then waits for the jobs to end

  void add_routes(httplib::Server& server);

  // --source when it is an image and `name` is kSourceName.
  std::optional<std::filesystem::path> source_image(const std::string& name) const;

  // Cancels every job and preview in flight (Ctrl-C, SIGTERM); they end within a fraction of a
  // second, removing their temporary files.
  void stop();

 private:
  std::filesystem::path movie_path(const std::string& name) const;
  InputFiles inputs() const;  // the studio's and --source
  nlohmann::json session() const;

  StudioExtrasConfig config_;
  std::filesystem::path folder_;  // canonical
  std::filesystem::path source_;  // canonical, or empty
  bool source_is_movie_ = false;
  std::unique_ptr<StudioContext> context_;
  MovieFrames movies_;
  FilterPreviews previews_;
  TexturePreviews textures_;
  std::unique_ptr<CameraFeed> camera_;
  JobQueue jobs_{2};  // last: destroyed (joined) first
};

// Movie files by extension (lower case, with the dot).
bool is_movie_name(const std::filesystem::path& name);

}  // namespace ifsfx::app
