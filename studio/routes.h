// SPDX-License-Identifier: Apache-2.0
// The studio's routes (docs/studio.md, "The API"), grouped by resource, one file each:
//   page_routes.cpp      the page (/, its scripts and styles) and the session
//   editor_routes.cpp    presets, the folder's presets, defaults, render, save
//   source_routes.cpp    steal sources, a source's pixels, uploads
//   file_routes.cpp      a file of the folder, served inline or as a download
//   job_routes.cpp       render jobs: list, submit, one job, cancel, preview
//   fit_routes.cpp       fit a shape (an upload or an image of the folder) in a job
//   video_routes.cpp     movies of the folder, a movie's frames, the camera's
//   superifs_routes.cpp  superIFS presets, save, texture previews
// Each registers its handlers on the server (the checks of studio/gate.h run first, and every
// answer is built by studio/http.h) and reaches the studio's state through StudioState.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include <httplib.h>

#include "ifs/preset.h"
#include "studio/context.h"
#include "studio/jobs.h"
#include "studio/superifs.h"
#include "studio/tab_renders.h"
#include "studio/video.h"

namespace ifsfx::app {

// What the routes share: one per server, alive while it serves.
struct StudioState {
  // `camera`: a V4L2 device, or empty; the others as StudioContext takes them.
  StudioState(std::filesystem::path folder, std::filesystem::path web,
              std::filesystem::path scratch, std::filesystem::path source, IfsPreset initial,
              std::string token, const std::string& camera);
  ~StudioState() { stop(); }  // then the members go, the job threads joined first

  // Asks the editor's renders, the previews and every job to stop (Ctrl-C, SIGTERM); they end
  // within a fraction of a second, removing their temporary files.
  void stop();

  StudioContext context;
  const IfsPreset initial;  // the preset of the command line
  const std::string token;  // the run's secret (studio/gate.h), for the page's cookie
  TabRenders renders;       // the editor's renders in flight
  std::mutex upload_mutex;  // one upload at a time: a free name stays free until written
  MovieFrames movies;
  FilterPreviews previews;
  TexturePreviews textures;
  std::unique_ptr<CameraFeed> camera;  // --camera, or null
  JobQueue jobs{2};                    // last: destroyed (joined) first
};

void add_page_routes(httplib::Server& server, StudioState& studio);
void add_editor_routes(httplib::Server& server, StudioState& studio);
void add_source_routes(httplib::Server& server, StudioState& studio);
void add_file_routes(httplib::Server& server, StudioState& studio);
void add_job_routes(httplib::Server& server, StudioState& studio);
void add_fit_routes(httplib::Server& server, StudioState& studio);
void add_video_routes(httplib::Server& server, StudioState& studio);
void add_superifs_routes(httplib::Server& server, StudioState& studio);

}  // namespace ifsfx::app
