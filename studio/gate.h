// SPDX-License-Identifier: Apache-2.0
// The checks every request of `ifsfx studio` passes before its route (docs/studio.md, "Safety"),
// in one place: the Host must name this server (a DNS-rebinding page reaches us under its own
// name), the Origin, when sent, must be this server (studio/hosts.h), and every /api/ request
// must carry the run's secret token, in the X-Ifsfx-Token header or the cookie that the page's
// URL sets.
//
//   const Gate gate(StudioHosts("127.0.0.1"), random_token());
//   if (auto refusal = gate.refusal(req, port)) send_error(res, 403, *refusal);
#pragma once

#include <optional>
#include <string>

#include <httplib.h>

#include "studio/hosts.h"

namespace ifsfx::app {

inline constexpr const char* kTokenHeader = "X-Ifsfx-Token";
inline constexpr const char* kTokenCookie = "ifsfx_token";

// 128 random bits as 32 hex digits, from the system's entropy (std::random_device reads
// getrandom).
std::string random_token();

// Whether `a` and `b` are the same secret, compared without an early exit, so that the time
// taken tells nothing about how much of a guess was right.
bool same_secret(const std::string& a, const std::string& b);

class Gate {
 public:
  Gate(StudioHosts hosts, std::string token) : hosts_(std::move(hosts)), token_(std::move(token)) {}

  const StudioHosts& hosts() const { return hosts_; }
  const std::string& token() const { return token_; }

  // Why `req` is refused (the message of a 403), or nullopt when it may reach its route, for a
  // server on `port`.
  std::optional<std::string> refusal(const httplib::Request& req, int port) const;

  // Whether `req` carries the token, in the header or the cookie.
  bool has_token(const httplib::Request& req) const;

 private:
  StudioHosts hosts_;
  std::string token_;
};

}  // namespace ifsfx::app
