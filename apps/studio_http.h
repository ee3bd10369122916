// SPDX-License-Identifier: Apache-2.0
// How `ifsfx studio`'s handlers answer (docs/studio.md): every error as a JSON object
// {"error": "what: rule (got X)"} with a 4xx (or 5xx) status, so that the page can show it and the
// server keeps running. Shared by the routes of apps/studio_command.cpp and apps/studio_routes.cpp.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "ifs/error.h"

namespace ifsfx::app {

// An error with its own HTTP status, for the answers no ErrorKind stands for: 409 (a file in use
// by a job), 413 (a body too large), 415 (not an image), 429 (too many jobs), 503 (the camera).
class HttpError : public std::runtime_error {
 public:
  HttpError(int status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  int status() const noexcept { return status_; }

 private:
  int status_;
};

inline void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

inline void send_json(httplib::Response& res, const nlohmann::json& body, int status = 200) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

inline int status_of(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::parse:
    case ErrorKind::invalid_ifs:
    case ErrorKind::invalid_argument:
    case ErrorKind::unsupported:
      return 400;
    case ErrorKind::not_found:
      return 404;
    case ErrorKind::interrupted:
      return 409;  // a newer request took over
    default:
      return 500;
  }
}

// Runs `handler`, turning every error into a JSON 4xx/5xx: a bad request never stops the server.
template <typename Handler>
void guarded(httplib::Response& res, Handler&& handler) {
  try {
    handler();
  } catch (const HttpError& e) {
    send_error(res, e.status(), e.what());
  } catch (const Error& e) {
    send_error(res, status_of(e.kind()), e.what());
  } catch (const nlohmann::json::exception& e) {
    send_error(res, 400, fmt::format("request: not valid JSON ({})", e.what()));
  } catch (const std::exception& e) {
    send_error(res, 500, fmt::format("internal error: {}", e.what()));
  }
}

}  // namespace ifsfx::app
