// SPDX-License-Identifier: Apache-2.0
#include "studio/server.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "ifs/error.h"
#include "studio/folder.h"
#include "studio/http.h"
#include "studio/routes.h"

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;

constexpr int kThreads = 32;  // connections served at once

// The local port of socket `fd`, or -1 for a socket of another kind.
int local_port(int fd) {
  sockaddr_storage address{};
  socklen_t size = sizeof address;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size) != 0) return -1;
  if (address.ss_family == AF_INET) return ntohs(reinterpret_cast<sockaddr_in&>(address).sin_port);
  if (address.ss_family == AF_INET6)
    return ntohs(reinterpret_cast<sockaddr_in6&>(address).sin6_port);
  return -1;
}

// Every connection to `port` shut down, so that connections idling in HTTP keep-alive (a browser
// tab holds some for seconds) end now and the server's threads can be joined at once: cpp-httplib
// waits out its keep-alive timeout otherwise, and tells nobody its sockets. A connection accepted
// on `port` is a socket of this process whose local port is `port`.
void shut_down_connections(int port) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc/self/fd", ec)) {
    const int fd = std::atoi(entry.path().filename().c_str());
    struct stat st {};
    if (fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode) && local_port(fd) == port)
      ::shutdown(fd, SHUT_RDWR);
  }
}

fs::path make_scratch() {
  std::string scratch = (fs::temp_directory_path() / "ifsfx-studio-XXXXXX").string();
  if (!mkdtemp(scratch.data()))
    throw Error(ErrorKind::io, fmt::format("{}: cannot create the scratch folder", scratch));
  return scratch;
}

std::unique_ptr<CameraFeed> open_camera(const std::string& device) {
  if (device.empty()) return nullptr;
  struct stat st {};
  if (stat(device.c_str(), &st) != 0 || !S_ISCHR(st.st_mode))
    throw Error(ErrorKind::not_found,
                fmt::format("--camera {}: no such device (a V4L2 camera is /dev/videoN)", device));
  return std::make_unique<CameraFeed>(device);
}

}  // namespace

fs::path find_source(const std::string& source, const fs::path& folder) {
  const fs::path given(source);
  std::error_code ec;
  for (const fs::path& place : {given, given.is_relative() ? folder / given : fs::path()}) {
    if (place.empty()) continue;
    const fs::path found = fs::canonical(place, ec);
    if (!ec && fs::is_regular_file(found, ec)) return found;
  }
  if (given.is_absolute())
    throw Error(ErrorKind::not_found, fmt::format("--source {}: no such file", source));
  throw Error(ErrorKind::not_found,
              fmt::format("--source {}: no such file (looked for {} and {})", source,
                          (fs::current_path(ec) / given).lexically_normal().string(),
                          (folder / given).lexically_normal().string()));
}

StudioState::StudioState(fs::path folder, fs::path web, fs::path scratch, fs::path source,
                         IfsPreset initial_preset, std::string secret, const std::string& device)
    : context(std::move(folder), std::move(web), std::move(scratch), std::move(source)),
      initial(std::move(initial_preset)),
      token(std::move(secret)),
      camera(open_camera(device)) {}

void StudioState::stop() {
  renders.cancel_all();
  jobs.stop_all();
  previews.stop_all();
  textures.stop_all();
}

Server::Server(ServerConfig config)
    : gate_(StudioHosts(config.listen), config.token.empty() ? random_token() : config.token),
      folder_(fs::canonical(config.folder)),
      wanted_port_(config.port) {
  if (!fs::is_directory(folder_))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("--folder {}: must be a folder", config.folder.string()));
  IfsPreset initial = load_ifs(config.preset);
  scratch_ = make_scratch();
  try {
    const fs::path source =
        config.source.empty() ? fs::path() : find_source(config.source, folder_);
    state_ = std::make_unique<StudioState>(folder_, config.web, scratch_, source,
                                           std::move(initial), gate_.token(), config.camera);
    state_->context.add_input(config.preset);
  } catch (...) {  // a missing --source or --camera: no scratch folder left behind
    std::error_code ec;
    fs::remove_all(scratch_, ec);
    throw;
  }
}

Server::~Server() {
  stop();
  state_.reset();  // its jobs end (and remove their temporary files) first
  std::error_code ec;
  fs::remove_all(scratch_, ec);
}

int Server::start() {
  configure();
  add_page_routes(http_, *state_);
  add_editor_routes(http_, *state_);
  add_source_routes(http_, *state_);
  add_file_routes(http_, *state_);
  add_job_routes(http_, *state_);
  add_fit_routes(http_, *state_);
  add_video_routes(http_, *state_);
  add_superifs_routes(http_, *state_);
  const std::string& address = hosts().listen();
  port_ = wanted_port_ == 0 ? http_.bind_to_any_port(address)
                            : (http_.bind_to_port(address, wanted_port_) ? wanted_port_ : -1);
  if (port_ <= 0)
    throw Error(ErrorKind::io, fmt::format("--port {}: cannot listen on {} (in use, or not an "
                                           "address of this machine?)",
                                           wanted_port_, address));
  serving_ = true;
  thread_ = std::thread([this] {
    http_.listen_after_bind();
    serving_ = false;
  });
  return port_;
}

bool Server::running() const {
  return serving_;
}

void Server::stop() {
  if (state_) state_->stop();
  http_.stop();
  if (port_ > 0) shut_down_connections(port_);
  if (thread_.joinable()) thread_.join();
}

std::string Server::url() const {
  return fmt::format("http://{}:{}/?token={}", hosts().url_host(), port_, gate_.token());
}

// The server's settings and the checks every request passes first (studio/gate.h).
void Server::configure() {
  // Each connection holds a thread while it is kept alive (a tab keeps up to six): enough
  // threads for a few tabs, and long-lived connections, so that a drag's renders reuse one.
  http_.new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
  http_.set_keep_alive_max_count(100000);
  http_.set_tcp_nodelay(true);                    // small answers at once, not after a delayed ACK
  http_.set_payload_max_length(kMaxUploadBytes);  // JSON bodies are checked to kMaxBody
  http_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const auto refusal = gate_.refusal(req, port_);
    if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
    send_error(res, 403, *refusal);
    return httplib::Server::HandlerResponse::Handled;
  });
  http_.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
  });
  http_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    send_error(res, res.status,
               res.status == 413 ? fmt::format("request: at most {} MiB (an upload; JSON: {} KiB)",
                                               kMaxUploadBytes >> 20, kMaxBody >> 10)
                                 : fmt::format("HTTP {}", res.status));
  });
  http_.set_exception_handler([](const httplib::Request&, httplib::Response& res,
                                 std::exception_ptr) { send_error(res, 500, "internal error"); });
}

}  // namespace ifsfx::app
