// SPDX-License-Identifier: Apache-2.0
// Where `ifsfx studio` listens and which names it answers to. By default the loopback only;
// `--listen ADDR` binds another address of this machine (0.0.0.0 or :: for all of them). The Host
// header must name this server, so that a DNS-rebinding page (an attacker's name resolved to our
// address) is refused: a loopback name, the --listen address, and, when other machines may
// connect, any IP literal and this machine's host name (or NAME.local) — never another name.
// Origin, when sent,
// must be such a host with our port.
#pragma once

#include <string>

namespace ifsfx::app {

class StudioHosts {
 public:
  // Throws Error{invalid_argument} unless `listen` is an IPv4 or IPv6 address (no host name:
  // the address decides who can connect, and a name could change what it resolves to).
  explicit StudioHosts(std::string listen = "127.0.0.1");

  const std::string& listen() const { return listen_; }
  // Whether only this machine can connect (127.0.0.0/8 or ::1).
  bool loopback_only() const { return loopback_; }
  // The host of the URL printed at start: the --listen address ([v6] bracketed), 127.0.0.1 for
  // the wildcard addresses.
  std::string url_host() const;

  // Host header "NAME" or "NAME:PORT" (PORT must be `port`).
  bool allowed_host(const std::string& host, int port) const;
  // Origin header "http://NAME:PORT".
  bool allowed_origin(const std::string& origin, int port) const;

 private:
  std::string listen_;
  bool loopback_ = true;
  bool wildcard_ = false;
  std::string machine_;  // this machine's host name (gethostname), with remote access
};

}  // namespace ifsfx::app
