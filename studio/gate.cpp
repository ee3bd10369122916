// SPDX-License-Identifier: Apache-2.0
#include "studio/gate.h"

#include <random>
#include <regex>

#include <fmt/format.h>

namespace ifsfx::app {

std::string random_token() {
  std::random_device device;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
  return token;
}

bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

bool Gate::has_token(const httplib::Request& req) const {
  if (req.has_header(kTokenHeader) && same_secret(req.get_header_value(kTokenHeader), token_))
    return true;
  const std::string cookie = req.get_header_value("Cookie");
  static const std::regex pattern(std::string(kTokenCookie) + "=([0-9a-f]+)");
  std::smatch m;
  return std::regex_search(cookie, m, pattern) && same_secret(m[1].str(), token_);
}

std::optional<std::string> Gate::refusal(const httplib::Request& req, int port) const {
  if (!hosts_.allowed_host(req.get_header_value("Host"), port))
    return "Host: must be 127.0.0.1, localhost or the --listen address (got " +
           req.get_header_value("Host") + ")";
  if (req.has_header("Origin") && !hosts_.allowed_origin(req.get_header_value("Origin"), port))
    return "Origin: must be this server (got " + req.get_header_value("Origin") + ")";
  if (req.path.rfind("/api/", 0) == 0 && !has_token(req))
    return std::string("token: every request needs the token of the URL printed at start");
  return std::nullopt;
}

}  // namespace ifsfx::app
