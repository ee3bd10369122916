// SPDX-License-Identifier: Apache-2.0
// How `ifsfx studio`'s handlers read requests and answer (docs/studio.md), one way for every
// route (studio/*_routes.cpp): JSON by send_json, every error by send_error as a JSON object
// {"error": "what: rule (got X)"} with a 4xx (or 5xx) status, so that the page can show it and
// the server keeps running (the status from the error's kind, as Jupyter's base handler writes
// its errors); handlers wrapped by `guard`; JSON bodies capped; the tab a request comes from.
#pragma once

#include <cstddef>
#include <exception>
#include <regex>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "ifs/error.h"

namespace ifsfx::app {

inline constexpr std::size_t kMaxBody = 1 << 20;  // JSON: a preset of 64 maps is a few kB
inline constexpr const char* kClientHeader = "X-Ifsfx-Client";

// An HTTP status of its own, where no ErrorKind says it: 409 (a file in use by a job), 413 (a
// body too large), 415 (not an image), 429 (too many jobs), 503 (the camera failed).
struct RequestError : std::runtime_error {
  RequestError(int code, const std::string& message) : std::runtime_error(message), status(code) {}
  int status;
};

inline void send_json(httplib::Response& res, const nlohmann::json& body, int status = 200) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

inline void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, {{"error", message}}, status);
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
  } catch (const RequestError& e) {
    send_error(res, e.status, e.what());
  } catch (const Error& e) {
    send_error(res, status_of(e.kind()), e.what());
  } catch (const nlohmann::json::exception& e) {
    send_error(res, 400, fmt::format("request: not valid JSON ({})", e.what()));
  } catch (const std::exception& e) {
    send_error(res, 500, fmt::format("internal error: {}", e.what()));
  }
}

// A route's handler with `guarded` around it.
template <typename Handle>
httplib::Server::Handler guard(Handle handle) {
  return [handle = std::move(handle)](const httplib::Request& req, httplib::Response& res) {
    guarded(res, [&] { handle(req, res); });
  };
}

// JSON bodies are read only up to kMaxBody (the server takes more for uploads).
inline void check_body_size(const httplib::Request& req) {
  if (req.body.size() > kMaxBody)
    throw RequestError(413, fmt::format("request: at most {} KiB of JSON (got {} bytes)",
                                        kMaxBody >> 10, req.body.size()));
}

// The body as JSON, checked to kMaxBody.
inline nlohmann::json json_body(const httplib::Request& req) {
  check_body_size(req);
  return nlohmann::json::parse(req.body);
}

// The tab a request comes from (X-Ifsfx-Client, an id the page draws): a newer request of a tab
// cancels or replaces only that tab's older one. Requests without one share the empty id.
inline std::string client_of(const httplib::Request& req) {
  const std::string id = req.get_header_value(kClientHeader);
  static const std::regex plain("[A-Za-z0-9_-]{0,64}");
  if (!std::regex_match(id, plain))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: letters, digits, _ and -, at most 64 (got '{}')", kClientHeader,
                            id.substr(0, 80)));
  return id;
}

}  // namespace ifsfx::app
