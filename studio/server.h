// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio`'s server as a library (docs/studio.md): an HTTP server (cpp-httplib) on the
// loopback (or the --listen address) that serves the page's files (studio/web) and a small JSON
// API, its routes grouped by resource (studio/routes.h). Safety: loopback only unless told
// otherwise, a per-run secret token on every API request, Host and Origin checked
// (studio/gate.h), bodies capped, files read and written only in the folder. The server never
// prints and never exits: the command (cli/studio_command.cpp) prints the URL and stops it on
// Ctrl-C.
//
//   Server server({.folder = "art", .web = "/usr/share/ifsfx/studio"});
//   server.start();
//   std::cout << server.url() << "\n";
//   ... server.stop();
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include <httplib.h>

#include "studio/gate.h"

namespace ifsfx::app {

struct StudioState;

struct ServerConfig {
  std::string preset = "barnsley-fern";  // opened at start: a shipped name or a preset file
  std::filesystem::path folder = ".";    // the only folder files are read from and written to
  std::filesystem::path web;             // the page's files (index.html, ...)
  std::string token;                     // the secret of every API request; empty: a random one
  std::string listen = "127.0.0.1";      // an IPv4 or IPv6 address of this machine
  int port = 0;                          // 0: a free one
  // A movie for the Video panel or an image to steal colours from (the page's "@source"); a
  // relative path is looked up in the current folder, then in `folder`.
  std::string source;
  std::string camera;  // a V4L2 device (/dev/videoN) for the live filter, or empty
};

class Server {
 public:
  // Checks the configuration and opens the preset: Error{invalid_argument} for a bad --listen or
  // a folder that is none, Error{not_found} for a missing source or camera, what load_ifs throws.
  // The renders' temporary files go to a private folder of $TMPDIR, removed at the end.
  explicit Server(ServerConfig config);
  ~Server();  // stop()
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Listens (Error{io} naming the port when it cannot) and serves on a thread of its own until
  // stop(); returns the port.
  int start();
  // Whether the server still serves (it may end by itself when listening fails).
  bool running() const;
  // Cancels the renders and jobs in flight, stops listening, ends the connections kept alive and
  // waits for the server's threads. Idempotent.
  void stop();

  // The page's URL with the token (the --listen address; 127.0.0.1 for a wildcard address).
  std::string url() const;
  const StudioHosts& hosts() const { return gate_.hosts(); }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  void configure();

  Gate gate_;
  std::filesystem::path folder_;  // canonical
  int port_ = 0;
  int wanted_port_ = 0;
  std::filesystem::path scratch_;
  std::unique_ptr<StudioState> state_;
  httplib::Server http_;
  std::thread thread_;
  std::atomic<bool> serving_{false};
};

// `source` as given on the command line, found: as it names it (relative to the current folder)
// or, when relative and not there, in `folder`. Throws Error{not_found} "--source NAME: no such
// file" naming both places it looked.
std::filesystem::path find_source(const std::string& source, const std::filesystem::path& folder);

}  // namespace ifsfx::app
