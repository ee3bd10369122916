// SPDX-License-Identifier: Apache-2.0
// Render jobs (docs/studio.md, studio/jobs.h): the list, a new job (studio/render_jobs.h), one
// job, its cancellation and the preview a job keeps (a fit's).
#include <string>

#include <fmt/format.h>

#include "ifs/error.h"
#include "studio/http.h"
#include "studio/render_jobs.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

int job_number(const httplib::Request& req) {
  const std::string digits = req.matches[1].str();
  if (digits.size() > 9)
    throw Error(ErrorKind::not_found, fmt::format("job: no such job (got {})", digits));
  return std::stoi(digits);
}

}  // namespace

void add_job_routes(httplib::Server& server, StudioState& studio) {
  JobQueue& jobs = studio.jobs;
  server.Get("/api/jobs", guard([&jobs](const httplib::Request&, httplib::Response& res) {
               send_json(res, {{"jobs", jobs.list()}});
             }));
  server.Post("/api/jobs", guard([&studio](const httplib::Request& req, httplib::Response& res) {
                const int id = submit_render_job(studio.jobs, json_body(req), studio.context);
                send_json(res, studio.jobs.get(id), 202);
              }));
  server.Get(R"(/api/jobs/(\d+))",
             guard([&jobs](const httplib::Request& req, httplib::Response& res) {
               send_json(res, jobs.get(job_number(req)));
             }));
  server.Post(R"(/api/jobs/(\d+)/cancel)",
              guard([&jobs](const httplib::Request& req, httplib::Response& res) {
                const int id = job_number(req);
                jobs.cancel(id);
                send_json(res, jobs.get(id));
              }));
  server.Get(R"(/api/jobs/(\d+)/preview)",
             guard([&jobs](const httplib::Request& req, httplib::Response& res) {
               const int id = job_number(req);
               const auto png = jobs.preview(id);
               if (!png)
                 throw Error(ErrorKind::not_found, fmt::format("job {}: no preview (yet)", id));
               res.set_content(*png, "image/png");
             }));
}

}  // namespace ifsfx::app
