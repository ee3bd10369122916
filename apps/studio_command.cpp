// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio [PRESET] [--port N] [--folder DIR] [--open]`: a local web editor served by the
// engine (docs/studio.md). An HTTP server (cpp-httplib) on 127.0.0.1 serves the page's files
// (apps/studio/web, installed in share/ifsfx/studio) and a small JSON API; the page sends the
// whole preset with every render, and the server renders it with `ifsfx render`'s library calls
// (apps/studio_render.h). Safety: loopback only, a per-run secret token on every API request (a
// header or the cookie set from the URL), Host and Origin checked against the loopback names
// (DNS rebinding, cross-site requests), bodies capped, files read and written only in --folder.
#include <spawn.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "apps/cli_errors.h"
#include "apps/commands.h"
#include "apps/stop_signals.h"
#include "apps/studio_fit.h"
#include "apps/studio_folder.h"
#include "apps/studio_http.h"
#include "apps/studio_render.h"
#include "apps/studio_routes.h"
#include "ifs/error.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"

extern char** environ;

namespace ifsfx::app {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr std::size_t kMaxBody = 1 << 20;  // a preset of 64 maps is a few kB
constexpr const char* kTokenHeader = "X-Ifsfx-Token";
constexpr const char* kTokenCookie = "ifsfx_token";

struct StudioArgs {
  std::string preset = "barnsley-fern";
  int port = 0;
  std::string folder = ".";
  bool open = false;
  std::string source;  // --source IMAGE|MOVIE
  std::string camera;  // --camera /dev/videoN
};

// 128 random bits as hex, from the system's entropy (std::random_device reads getrandom).
std::string random_token() {
  std::random_device device;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
  return token;
}

// Compares without an early exit, so that the time taken tells nothing about the token.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

// The page's files: installed beside the program (share/ifsfx/studio), or in the source tree for
// a build that is not installed.
fs::path web_folder() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (!ec) candidates.push_back(exe.parent_path() / IFSFX_STUDIO_FROM_LIBEXECDIR);
  candidates.push_back(IFSFX_STUDIO_SOURCE_DIR);
  for (const auto& c : candidates)
    if (fs::is_regular_file(c / "index.html", ec)) return c;
  throw Error(ErrorKind::not_found,
              fmt::format("studio: the page's files are missing (got none in {})",
                          candidates.front().lexically_normal().string()));
}

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Studio {
 public:
  explicit Studio(const StudioArgs& args)
      : args_(args), web_(web_folder()), token_(random_token()) {
    folder_ = fs::canonical(args.folder);
    if (!fs::is_directory(folder_))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("--folder {}: must be a folder", args.folder));
    initial_ = load_ifs(args.preset);
    inputs_.add(args.preset);
    // The renders' temporary files, in a private folder of $TMPDIR removed at the end.
    std::string scratch = (fs::temp_directory_path() / "ifsfx-studio-XXXXXX").string();
    if (!mkdtemp(scratch.data()))
      throw Error(ErrorKind::io, fmt::format("{}: cannot create the scratch folder", scratch));
    scratch_ = scratch;
    // ---- render jobs, fit, video, camera, superIFS (apps/studio_routes.h) ----
    try {
      extras_ = std::make_unique<StudioExtras>(StudioExtrasConfig{
          .folder = folder_,
          .scratch = scratch_,
          .web = web_,
          .inputs = inputs_,
          .source = args.source,
          .camera = args.camera,
          .source_path = [this](const std::string& name) { return source_path(name); }});
    } catch (...) {  // a missing --source or --camera: no scratch folder left behind
      std::error_code ec;
      fs::remove_all(scratch_, ec);
      throw;
    }
  }
  ~Studio() {
    extras_.reset();  // its jobs end (and remove their temporary files) first
    std::error_code ec;
    fs::remove_all(scratch_, ec);
  }

  void run() {
    routes();
    port_ = args_.port == 0 ? server_.bind_to_any_port("127.0.0.1")
                            : (server_.bind_to_port("127.0.0.1", args_.port) ? args_.port : -1);
    if (port_ <= 0)
      throw Error(ErrorKind::io,
                  fmt::format("--port {}: cannot listen on 127.0.0.1 (in use?)", args_.port));
    const std::string url = fmt::format("http://127.0.0.1:{}/?token={}", port_, token_);
    std::printf("ifsfx studio: %s\n", url.c_str());
    std::fflush(stdout);
    if (args_.open) open_browser(url);
    // Ctrl-C or SIGTERM: cancel the render in flight and stop listening, polled every 20 ms.
    std::thread watcher([this] {
      while (!StopSignals::stop_flag() && !done_)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      cancel_current();
      extras_->stop();
      server_.stop();
    });
    server_.listen_after_bind();
    done_ = true;
    watcher.join();
    if (StopSignals::stop_flag()) throw Error(ErrorKind::interrupted, "studio: interrupted");
  }

 private:
  // Host must name the loopback (a DNS-rebinding page reaches us under its own name), Origin,
  // when sent, must be this server.
  bool loopback_host(const std::string& host) const {
    for (const char* name : {"127.0.0.1", "localhost", "[::1]"})
      if (host == name || host == fmt::format("{}:{}", name, port_)) return true;
    return false;
  }
  bool allowed_origin(const std::string& origin) const {
    for (const char* name : {"127.0.0.1", "localhost", "[::1]"})
      if (origin == fmt::format("http://{}:{}", name, port_)) return true;
    return false;
  }
  bool has_token(const httplib::Request& req) const {
    if (req.has_header(kTokenHeader) && same_secret(req.get_header_value(kTokenHeader), token_))
      return true;
    const std::string cookie = req.get_header_value("Cookie");
    static const std::regex pattern(std::string(kTokenCookie) + "=([0-9a-f]+)");
    std::smatch m;
    return std::regex_search(cookie, m, pattern) && same_secret(m[1].str(), token_);
  }

  // A name in --folder: one path component, no hidden file, a regular file inside the folder
  // once links are followed.
  fs::path folder_file(const std::string& name, bool must_exist) const {
    return StudioFolder(folder_).file(name, must_exist);
  }

  fs::path source_path(const std::string& name) const {
    if (name == "sample") return web_ / "sample.png";
    if (auto image = extras_->source_image(name)) return *image;
    return folder_file(name, true);
  }

  void cancel_current() {
    std::lock_guard lock(mutex_);
    if (current_) current_->store(true);
  }

  void routes() {
    server_.set_payload_max_length(kMaxUpload);  // uploads; every other request: kMaxBody
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!loopback_host(req.get_header_value("Host"))) {
        send_error(
            res, 403,
            "Host: must be 127.0.0.1 or localhost (got " + req.get_header_value("Host") + ")");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.has_header("Origin") && !allowed_origin(req.get_header_value("Origin"))) {
        send_error(res, 403,
                   "Origin: must be this server (got " + req.get_header_value("Origin") + ")");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.path.rfind("/api/", 0) == 0 && !has_token(req)) {
        send_error(res, 403, "token: every request needs the token of the URL printed at start");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (!StudioExtras::takes_upload(req.path)) {
        if (req.get_header_value<std::uint64_t>("Content-Length") > kMaxBody) {
          send_error(res, 413,
                     fmt::format("request: at most {} bytes (got {})", kMaxBody,
                                 req.get_header_value("Content-Length")));
          return httplib::Server::HandlerResponse::Handled;
        }
        if (req.has_header("Transfer-Encoding")) {
          send_error(res, 411, "request: a body needs a Content-Length here");
          return httplib::Server::HandlerResponse::Handled;
        }
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });
    server_.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
      res.set_header("Cache-Control", "no-store");
      res.set_header("X-Content-Type-Options", "nosniff");
    });
    server_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) send_error(res, res.status, fmt::format("HTTP {}", res.status));
    });
    server_.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          send_error(res, 500, "internal error");
        });

    // The page: index.html (which sets the token's cookie from the URL) and its few files.
    server_.Get("/", [this](const httplib::Request& req, httplib::Response& res) {
      if (req.has_param("token") && same_secret(req.get_param_value("token"), token_))
        res.set_header("Set-Cookie", fmt::format("{}={}; Path=/; HttpOnly; SameSite=Strict",
                                                 kTokenCookie, token_));
      res.set_header("Content-Security-Policy",
                     "default-src 'self'; img-src 'self' blob: data:; connect-src 'self'");
      res.set_content(read_whole(web_ / "index.html"), "text/html; charset=utf-8");
    });
    const std::vector<std::pair<std::string, std::string>> files{
        {"studio.js", "text/javascript"}, {"studio.css", "text/css"}, {"sample.png", "image/png"}};
    for (const auto& [name, type] : files)
      server_.Get("/" + name, [this, name = name, type = type](const httplib::Request&,
                                                               httplib::Response& res) {
        res.set_content(read_whole(web_ / name), type.c_str());
      });

    server_.Get("/api/presets", [](const httplib::Request&, httplib::Response& res) {
      guarded(res, [&] {
        json list = json::array();
        for (const auto& p : list_shipped_presets())
          if (p.problem.empty())
            list.push_back({{"name", p.name},
                            {"maps", p.maps},
                            {"contraction", p.contraction},
                            {"description", p.description}});
        res.set_content(list.dump(), "application/json");
      });
    });
    // A shipped preset by name; no name: the one of the command line.
    server_.Get("/api/preset", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        if (!req.has_param("name")) {
          res.set_content(preset_to_json(initial_).dump(), "application/json");
          return;
        }
        const std::string name = req.get_param_value("name");
        bool shipped = false;
        for (const auto& p : list_shipped_presets()) shipped |= p.name == name && p.problem.empty();
        if (!shipped)
          throw Error(ErrorKind::not_found,
                      fmt::format("preset: not a shipped preset (got '{}')", name));
        res.set_content(preset_to_json(load_ifs(name)).dump(), "application/json");
      });
    });
    server_.Get("/api/sources", [this](const httplib::Request&, httplib::Response& res) {
      guarded(res, [&] {
        json list = json::array({"sample"});
        if (extras_->source_image(StudioExtras::kSourceName))
          list.push_back(StudioExtras::kSourceName);
        static const std::regex image(".*\\.(png|jpe?g|tiff?|exr|bmp|webp)", std::regex::icase);
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(folder_)) {
          const std::string name = entry.path().filename().string();
          if (name[0] != '.' && entry.is_regular_file() && std::regex_match(name, image))
            names.push_back(name);
        }
        std::sort(names.begin(), names.end());
        for (const auto& n : names) list.push_back(n);
        res.set_content(list.dump(), "application/json");
      });
    });
    server_.Post("/api/render", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        const StudioRender render = studio_render_from_json(
            json::parse(req.body), [this](const std::string& n) { return source_path(n); });
        // A newer request cancels the one in flight (its render throws Error{interrupted}).
        auto flag = std::make_shared<std::atomic<bool>>(false);
        {
          std::lock_guard lock(mutex_);
          if (current_) current_->store(true);
          current_ = flag;
        }
        const auto start = std::chrono::steady_clock::now();
        const StudioPicture picture = render_png(render, CancelToken(flag.get()), scratch_);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        {
          std::lock_guard lock(mutex_);
          if (current_ == flag) current_.reset();
        }
        res.set_header("X-Ifsfx-Render-Ms", fmt::format("{:.1f}", ms));
        const Box& v = picture.view;
        res.set_header("X-Ifsfx-View", fmt::format("{},{},{},{}", v.x0, v.y0, v.x1, v.y1));
        res.set_content(picture.png, "image/png");
      });
    });
    // Saves the request's preset as TOML in --folder under the output policy.
    server_.Post("/api/save", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        const json body = json::parse(req.body);
        const IfsPreset preset = preset_from_json(body);
        std::string name = body.value("file", "");
        if (name.size() < 6 || name.substr(name.size() - 5) != ".toml")
          throw Error(ErrorKind::invalid_argument,
                      fmt::format("file: a name ending in .toml (got '{}')", name));
        write_file(folder_file(name, false), preset.text, {.inputs = inputs_});
        res.set_content(json{{"saved", name}}.dump(), "application/json");
      });
    });
    // ---- render jobs, fit, video, camera, superIFS (apps/studio_routes.h) ----
    extras_->add_routes(server_);
  }

  static void open_browser(const std::string& url) {
    pid_t pid = 0;
    const char* argv[] = {"xdg-open", url.c_str(), nullptr};
    if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) !=
        0)
      std::fputs("ifsfx: --open: cannot run xdg-open; open the URL above by hand\n", stderr);
  }

  StudioArgs args_;
  fs::path web_, folder_, scratch_;
  std::string token_;
  IfsPreset initial_;
  InputFiles inputs_;
  httplib::Server server_;
  int port_ = 0;
  std::atomic<bool> done_{false};
  std::mutex mutex_;
  std::shared_ptr<std::atomic<bool>> current_;  // the stop flag of the render in flight
  std::unique_ptr<StudioExtras> extras_;        // jobs, fit, video, camera, superIFS
};

}  // namespace

void add_studio_command(CLI::App& app) {
  auto args = std::make_shared<StudioArgs>();
  auto* cmd = app.add_subcommand(
      "studio",
      "A local web editor: drag the maps of an IFS and watch the picture (docs/studio.md)");
  cmd->add_option("preset", args->preset,
                  "Preset to open: a shipped name, a .toml/.ifs path, or FILE.ifs:NAME")
      ->capture_default_str();
  cmd->add_option("--port", args->port, "Port on 127.0.0.1 (0: a free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--folder", args->folder,
                  "Folder of source images (steal mode) and saved presets")
      ->capture_default_str();
  cmd->add_flag("--open", args->open, "Open the page in the browser (xdg-open)");
  cmd->add_option("--source", args->source,
                  "A movie to open in the video panel, or an image to steal colours from (any "
                  "folder; the page calls it @source)");
  cmd->add_option("--camera", args->camera,
                  "A V4L2 camera (/dev/videoN) for the live filter in the page");
  cmd->callback([args] {
    StopSignals signals;
    Studio studio(*args);
    studio.run();
  });
}

}  // namespace ifsfx::app
