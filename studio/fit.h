// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio`'s fit (docs/studio.md): a shape dropped on the page (or an image of the folder)
// fitted by the collage theorem in a render job, as `ifsfx fit` fits it (run/fit_run.h), with
// the phase and the best IoU so far as its progress; the fitted preset comes back as the job's
// result, for the editor to open.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "studio/context.h"
#include "studio/jobs.h"

namespace ifsfx::app {

// Starts a fit of an uploaded image: `bytes` is the file (PNG, JPEG, TIFF, BMP, GIF or WebP, told
// by its first bytes), `settings` the request's query: maps (1..32, default 4), seconds (the time
// budget, 0..600, default 5; 0: none), evaluations (default 250000), size (the working raster,
// 16..512, default 128), seed, init (search, moments), threshold (0..1) and invert, and name
// (the shape's file name, default "shape"), as `ifsfx fit` takes them.
// Returns the job's number. Throws RequestError 415 for bytes that are no image of those kinds,
// Error{parse} or Error{invalid_argument} for a bad setting.
int submit_upload_fit(JobQueue& jobs, const std::string& bytes,
                      const std::multimap<std::string, std::string>& settings,
                      StudioContext& context);

// The same for an image of the folder: {"file": NAME, "maps": 4, "seconds": 5, ...}.
int submit_folder_fit(JobQueue& jobs, const nlohmann::json& body, StudioContext& context);

}  // namespace ifsfx::app
