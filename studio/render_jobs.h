// SPDX-License-Identifier: Apache-2.0
// The render jobs of `ifsfx studio` (docs/studio.md): a full-size still, the movie filter over a
// movie of the folder, a texture sequence — each made by the command's own function
// (studio_image as `ifsfx render`, filter_movie as `ifsfx filter`, write_textures as `ifsfx
// texture`), so that the files equal the command line's, and written into the folder under the
// output policy: never over an input, a temporary name then a rename, nothing left by a cancelled
// job but the movie filter's playable STEM.partial.EXT of the frames done.
#pragma once

#include <nlohmann/json.hpp>

#include "studio/context.h"
#include "studio/jobs.h"

namespace ifsfx::app {

// Checks a job request and queues it; returns its number. body["kind"]:
//   "still":   a render request (/api/render's fields) and "file": NAME.png|.tif|.exr|.jpg,
//              "bits": 8 or 16;
//   "filter":  a preset, "movie": NAME (or "@source"), "file": NAME.mp4|.mkv|.mov|.avi|.webm,
//              and `ifsfx filter`'s "exact", "view", "mix", "background", "animate" (none,
//              drift), "drift_amount", "drift_speed", "seed", "frames" ("A:B"), "size";
//   "texture": "superifs" (the page's superIFS), "file": NAME.png (frames NAME_0001.png, ...),
//              and `ifsfx texture`'s "V", "mode", "size", "frames", "crossfade", "seed",
//              "steps", "buffer", "source" (steal mode).
// Bad requests throw before anything is queued: Error{parse} or Error{invalid_argument} naming
// the field, what check_output throws for an output that is an input, RequestError 409 for a file
// another job uses.
int submit_render_job(JobQueue& jobs, const nlohmann::json& body, StudioContext& context);

}  // namespace ifsfx::app
