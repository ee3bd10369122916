// SPDX-License-Identifier: Apache-2.0
// Fit (docs/studio.md, studio/fit.h): a shape dropped on the page (the body, its settings in the
// query) or an image of the folder (JSON), fitted in a render job.
#include <string>

#include "studio/fit.h"
#include "studio/http.h"
#include "studio/routes.h"

namespace ifsfx::app {

void add_fit_routes(httplib::Server& server, StudioState& studio) {
  server.Post("/api/fit", guard([&studio](const httplib::Request& req, httplib::Response& res) {
                const bool is_json =
                    req.get_header_value("Content-Type").rfind("application/json", 0) == 0;
                const int id =
                    is_json ? submit_folder_fit(studio.jobs, json_body(req), studio.context)
                            : submit_upload_fit(studio.jobs, req.body, req.params, studio.context);
                send_json(res, studio.jobs.get(id), 202);
              }));
}

}  // namespace ifsfx::app
