// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio [PRESET] [--source IMAGE|MOVIE] [--camera /dev/videoN] [--port N] [--listen ADDR]
// [--folder DIR] [--open]`: a local web editor served by the engine (docs/studio.md). An HTTP
// server (cpp-httplib) on 127.0.0.1 (or --listen's address) serves the page's files
// (studio/web, installed in share/ifsfx/studio) and a small JSON API; the page sends the
// whole preset with every render, and the server renders it with `ifsfx render`'s library calls
// (studio/render.h). Safety: loopback only unless --listen, a per-run secret token on every
// API request (a header or the cookie set from the URL), Host and Origin checked (studio_hosts.h)
// (DNS rebinding, cross-site requests), bodies capped, files read and written only in --folder.
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
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
#include <opencv2/imgproc.hpp>

#include "cli/cli_errors.h"
#include "cli/commands.h"
#include "cli/stop_signals.h"
#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/output_file.h"
#include "ifs/preset.h"
#include "ifs/render.h"
#include "ifs/steal_map.h"
#include "studio/folder.h"
#include "studio/hosts.h"
#include "studio/http.h"
#include "studio/render.h"
#include "studio/routes.h"

extern char** environ;

namespace ifsfx::app {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kMaxMaps = 64;             // as preset_from_json takes
constexpr double kSourcePreview = 1024;  // the source beside the canvas, pixels a side
constexpr int kThreads = 32;             // connections served at once
constexpr const char* kTokenHeader = "X-Ifsfx-Token";
constexpr const char* kTokenCookie = "ifsfx_token";

struct StudioArgs {
  std::string preset = "barnsley-fern";
  int port = 0;
  std::string listen = "127.0.0.1";  // --listen ADDR (studio/hosts.h)
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

// Every socket of this process shut down, so that connections idling in HTTP keep-alive (a
// browser tab holds some for seconds) end now and the server's threads can be joined at once:
// cpp-httplib waits out its keep-alive timeout otherwise. Only at the end; the studio holds no
// other socket.
void shut_down_sockets() {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc/self/fd", ec)) {
    const int fd = std::atoi(entry.path().filename().c_str());
    struct stat st {};
    if (fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode)) ::shutdown(fd, SHUT_RDWR);
  }
}

// A positive whole number query parameter no larger than `most`.
int count_param(const httplib::Request& req, const char* name, int most) {
  const std::string text = req.get_param_value(name);
  static const std::regex digits("[0-9]{1,6}");
  const int value = std::regex_match(text, digits) ? std::stoi(text) : 0;
  if (value < 1 || value > most)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: a whole number from 1 to {} (got '{}')", name, most, text));
  return value;
}

class Studio {
 public:
  explicit Studio(const StudioArgs& args)
      : args_(args), web_(web_folder()), token_(random_token()), hosts_(args.listen) {
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
    // ---- render jobs, fit, video, camera, superIFS (studio/routes.h) ----
    try {
      extras_ = std::make_unique<StudioExtras>(StudioExtrasConfig{
          .folder = folder_,
          .scratch = scratch_,
          .web = web_,
          .inputs = [this] { return inputs(); },
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
    configure();
    routes();
    const std::string& address = hosts_.listen();
    port_ = args_.port == 0 ? server_.bind_to_any_port(address)
                            : (server_.bind_to_port(address, args_.port) ? args_.port : -1);
    if (port_ <= 0)
      throw Error(ErrorKind::io, fmt::format("--port {}: cannot listen on {} (in use, or not an "
                                             "address of this machine?)",
                                             args_.port, address));
    if (!hosts_.loopback_only())
      fmt::print(stderr,
                 "ifsfx: warning: studio: listening on {} port {}: other machines can connect; "
                 "whoever has the URL's token can render and read and write files in {}\n",
                 address, port_, folder_.string());
    const std::string url = fmt::format("http://{}:{}/?token={}", hosts_.url_host(), port_, token_);
    std::printf("ifsfx studio: %s\n", url.c_str());
    std::fflush(stdout);
    if (args_.open) open_browser(url);
    // Ctrl-C or SIGTERM: cancel the renders in flight and stop listening, polled every 20 ms.
    std::thread watcher([this] {
      while (!StopSignals::stop_flag() && !done_)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      cancel_all();
      extras_->stop();
      server_.stop();
      shut_down_sockets();
    });
    server_.listen_after_bind();
    done_ = true;
    watcher.join();
    if (StopSignals::stop_flag()) throw Error(ErrorKind::interrupted, "studio: interrupted");
  }

 private:
  bool has_token(const httplib::Request& req) const {
    if (req.has_header(kTokenHeader) && same_secret(req.get_header_value(kTokenHeader), token_))
      return true;
    const std::string cookie = req.get_header_value("Cookie");
    static const std::regex pattern(std::string(kTokenCookie) + "=([0-9a-f]+)");
    std::smatch m;
    return std::regex_search(cookie, m, pattern) && same_secret(m[1].str(), token_);
  }

  fs::path source_path(const std::string& name) const {
    if (name == "sample") return web_ / "sample.png";
    if (auto image = extras_->source_image(name)) return *image;
    if (!is_image_name(name))
      throw Error(ErrorKind::invalid_argument,
                  fmt::format("source: an image of --folder (got '{}')", name));
    return folder_file(folder_, name, true);
  }

  InputFiles inputs() {
    std::lock_guard lock(mutex_);
    return inputs_;
  }
  void add_input(const fs::path& path) {
    std::lock_guard lock(mutex_);
    inputs_.add(path);
  }

  // Starts a render of tab `client`: cancels that tab's render in flight. Returns the new stop
  // flag; finish_render forgets it.
  std::shared_ptr<std::atomic<bool>> start_render(const std::string& client) {
    auto flag = std::make_shared<std::atomic<bool>>(false);
    std::lock_guard lock(mutex_);
    auto& current = in_flight_[client];
    if (current) current->store(true);
    current = flag;
    return flag;
  }
  void finish_render(const std::string& client, const std::shared_ptr<std::atomic<bool>>& flag) {
    std::lock_guard lock(mutex_);
    const auto it = in_flight_.find(client);
    if (it != in_flight_.end() && it->second == flag) in_flight_.erase(it);
  }
  void cancel_all() {
    std::lock_guard lock(mutex_);
    for (auto& [client, flag] : in_flight_) flag->store(true);
  }

  // The server's settings and the checks every request passes first.
  void configure() {
    // Each connection holds a thread while it is kept alive (a tab keeps up to six): enough
    // threads for a few tabs, and long-lived connections, so that a drag's renders reuse one.
    server_.new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
    server_.set_keep_alive_max_count(100000);
    server_.set_tcp_nodelay(true);  // small answers at once, not after a delayed ACK
    server_.set_payload_max_length(kMaxUploadBytes);  // JSON bodies are checked to kMaxBody
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      // Host must name this server (a DNS-rebinding page reaches us under its own name), Origin,
      // when sent, must be this server (studio/hosts.h).
      if (!hosts_.allowed_host(req.get_header_value("Host"), port_)) {
        send_error(res, 403,
                   "Host: must be 127.0.0.1, localhost or the --listen address (got " +
                       req.get_header_value("Host") + ")");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.has_header("Origin") &&
          !hosts_.allowed_origin(req.get_header_value("Origin"), port_)) {
        send_error(res, 403,
                   "Origin: must be this server (got " + req.get_header_value("Origin") + ")");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.path.rfind("/api/", 0) == 0 && !has_token(req)) {
        send_error(res, 403, "token: every request needs the token of the URL printed at start");
        return httplib::Server::HandlerResponse::Handled;
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });
    server_.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
      res.set_header("Cache-Control", "no-store");
      res.set_header("X-Content-Type-Options", "nosniff");
    });
    server_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (!res.body.empty()) return;
      send_error(res, res.status,
                 res.status == 413
                     ? fmt::format("request: at most {} MiB (an upload; JSON: {} KiB)",
                                   kMaxUploadBytes >> 20, kMaxBody >> 10)
                     : fmt::format("HTTP {}", res.status));
    });
    server_.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          send_error(res, 500, "internal error");
        });
  }

  void routes() {
    // ---- The editor's routes: the page, presets, the folder, renders, saves (docs/studio.md,
    // "The API"). Other parts of the studio register theirs after this block. ----

    // The page: index.html (which sets the token's cookie from the URL) and its few files.
    server_.Get("/", [this](const httplib::Request& req, httplib::Response& res) {
      if (req.has_param("token") && same_secret(req.get_param_value("token"), token_))
        res.set_header("Set-Cookie", fmt::format("{}={}; Path=/; HttpOnly; SameSite=Strict",
                                                 kTokenCookie, token_));
      res.set_header("Content-Security-Policy",
                     "default-src 'self'; img-src 'self' blob: data:; connect-src 'self'");
      res.set_content(read_whole(web_ / "index.html"), "text/html; charset=utf-8");
    });
    // The page's other files (its ES modules, styles and the sample source): plain names of the
    // web folder only.
    server_.Get(R"(/([a-z][a-z0-9_-]*)\.(js|css|png))",
                [this](const httplib::Request& req, httplib::Response& res) {
                  const fs::path path = web_ / (req.matches[1].str() + "." + req.matches[2].str());
                  std::error_code ec;
                  if (!fs::is_regular_file(path, ec)) {
                    send_error(res, 404, fmt::format("{}: no such file", req.path));
                    return;
                  }
                  const std::string ext = req.matches[2].str();
                  res.set_content(read_whole(path), ext == "js"    ? "text/javascript"
                                                    : ext == "css" ? "text/css"
                                                                   : "image/png");
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
    // A preset: shipped (name=), of the folder (file= and, for a Fractint file, entry=), or, with
    // neither, the one of the command line. A folder preset becomes an input (never saved over);
    // NAME.toml brings its colouring NAME.colouring.toml when there is one.
    server_.Get("/api/preset", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        if (req.has_param("file")) {
          const std::string file = req.get_param_value("file");
          const IfsPreset preset = open_folder_preset(folder_, file, req.get_param_value("entry"));
          add_input(folder_file(folder_, file, true));
          json body = preset_to_json(preset);
          body["origin_file"] = file;
          if (preset.format == PresetFormat::fractint) body["origin_entry"] = preset.ifs.name;
          if (preset.format == PresetFormat::toml) attach_colouring(body, file, preset.ifs);
          res.set_content(body.dump(), "application/json");
          return;
        }
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
    server_.Get("/api/folder", [this](const httplib::Request&, httplib::Response& res) {
      guarded(res, [&] { res.set_content(folder_presets(folder_).dump(), "application/json"); });
    });
    // What the page needs for N maps and the server computes: the default palette (the colours
    // of tops and measure without "colours") and the default colouring IFS on the unit square.
    server_.Get("/api/defaults", [](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        const auto n = static_cast<std::size_t>(count_param(req, "maps", kMaxMaps));
        json colours = json::array();
        for (std::size_t i = 0; i < n; ++i) colours.push_back(hex_colour(palette_colour(i, n)));
        res.set_content(
            json{{"colours", colours}, {"colouring", maps_to_json(default_colouring(n))}}.dump(),
            "application/json");
      });
    });
    server_.Get("/api/sources", [this](const httplib::Request&, httplib::Response& res) {
      guarded(res, [&] {
        json list = json::array({"sample"});
        if (extras_->source_image(StudioExtras::kSourceName))
          list.push_back(StudioExtras::kSourceName);
        for (const auto& name : folder_sources(folder_)) list.push_back(name);
        res.set_content(list.dump(), "application/json");
      });
    });
    // A source image to show beside the canvas: RGBA rows, at most kSourcePreview pixels a side,
    // with X-Ifsfx-Size (what is sent) and X-Ifsfx-Source-Size (the file's own).
    server_.Get("/api/source", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        cv::Mat image;
        try {
          image = read_image(source_path(req.get_param_value("name"))).pixels;
        } catch (const Error& e) {
          // A file of the folder that is no readable image: the request's fault, not the server's.
          if (e.kind() != ErrorKind::io) throw;
          throw Error(ErrorKind::invalid_argument, e.what());
        }
        const double scale =
            std::min(1.0, kSourcePreview / static_cast<double>(std::max(image.cols, image.rows)));
        cv::Mat shown = image;
        if (scale < 1)
          cv::resize(image, shown,
                     cv::Size(std::max(1, static_cast<int>(std::lround(image.cols * scale))),
                              std::max(1, static_cast<int>(std::lround(image.rows * scale)))),
                     0, 0, cv::INTER_AREA);
        res.set_header("X-Ifsfx-Size", fmt::format("{}x{}", shown.cols, shown.rows));
        res.set_header("X-Ifsfx-Source-Size", fmt::format("{}x{}", image.cols, image.rows));
        res.set_content(rgba_bytes(shown), "application/octet-stream");
      });
    });
    server_.Post("/api/render", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        const auto received = std::chrono::steady_clock::now();
        check_body_size(req);
        const std::string client = client_of(req);
        const StudioRender render = studio_render_from_json(
            json::parse(req.body), [this](const std::string& n) { return source_path(n); });
        // A newer request of the same tab cancels this one (its render throws
        // Error{interrupted}: 409).
        const auto flag = start_render(client);
        std::optional<StudioPicture> picture;
        try {
          picture = render_picture(render, CancelToken(flag.get()));
        } catch (...) {
          finish_render(client, flag);
          throw;
        }
        finish_render(client, flag);
        const Box& v = picture->view;
        res.set_header("X-Ifsfx-View", fmt::format("{},{},{},{}", v.x0, v.y0, v.x1, v.y1));
        res.set_header("X-Ifsfx-Size", fmt::format("{}x{}", render.size.width, render.size.height));
        res.set_header("X-Ifsfx-Render-Ms", fmt::format("{:.1f}", picture->render_ms));
        res.set_header("X-Ifsfx-Encode-Ms", fmt::format("{:.1f}", picture->encode_ms));
        res.set_header("X-Ifsfx-Request-Ms",
                       fmt::format("{:.1f}", std::chrono::duration<double, std::milli>(
                                                 std::chrono::steady_clock::now() - received)
                                                 .count()));
        if (render.colouring)
          res.set_header("X-Ifsfx-Colouring", maps_to_json(*render.colouring).dump());
        res.set_content(std::move(picture->bytes), render.format == PictureFormat::png
                                                       ? "image/png"
                                                       : "application/octet-stream");
      });
    });
    // Saves the request's preset as TOML in --folder under the output policy, and its colouring
    // (when the request has one) as NAME.colouring.toml beside it, both or neither.
    server_.Post("/api/save", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        check_body_size(req);
        const json body = json::parse(req.body);
        const IfsPreset preset = preset_from_json(body);
        std::string name = body.value("file", "");
        if (name.size() < 6 || name.substr(name.size() - 5) != ".toml")
          throw Error(ErrorKind::invalid_argument,
                      fmt::format("file: a name ending in .toml (got '{}')", name));
        const OutputOptions policy{.inputs = inputs()};
        std::vector<OutputFile> files;
        files.emplace_back(folder_file(folder_, name, false), policy);
        write_file(files.back(), preset.text);
        json answer{{"saved", name}};
        const std::string cname = colouring_file_name(name);
        const std::string stem = name.substr(0, name.size() - 5);
        if (const auto g = colouring_preset(body, stem + "-colouring")) {
          colouring_from_json(body, preset.ifs);  // the count and the fit checked as a render would
          files.emplace_back(folder_file(folder_, cname, false), policy);
          write_file(files.back(), g->text);
          answer["colouring"] = cname;
        }
        commit_together(files);
        res.set_content(answer.dump(), "application/json");
      });
    });
    // An image dropped on the page (the body's bytes), saved in --folder as ?name=, or under a
    // free name beside it: answers {"saved": NAME}.
    server_.Post("/api/upload", [this](const httplib::Request& req, httplib::Response& res) {
      guarded(res, [&] {
        std::lock_guard lock(upload_mutex_);  // one at a time: the free name stays free
        const std::string saved =
            save_upload(folder_, req.get_param_value("name"), req.body, scratch_);
        res.set_content(json{{"saved", saved}}.dump(), "application/json");
      });
    });

    // ---- End of the editor's routes. ----

    // ---- Render jobs, fit, video, camera, superIFS (studio/routes.h). ----
    extras_->add_routes(server_);
  }

  // NAME.colouring.toml beside a folder preset NAME.toml, as the preset's "colouring" when it has
  // as many maps (an input then, as the preset); a warning in the preset otherwise.
  void attach_colouring(json& body, const std::string& file, const Ifs& F) {
    const std::string cname = colouring_file_name(file);
    std::error_code ec;
    if (!fs::exists(folder_ / cname, ec)) return;
    try {
      const IfsPreset g =
          load_ifs(folder_file(folder_, cname, true).string(), {.allow_expansive = true});
      if (g.ifs.size() != F.size())
        throw Error(ErrorKind::invalid_ifs, fmt::format("{}: one map per map of {} (got {} for {})",
                                                        cname, file, g.ifs.size(), F.size()));
      body["colouring"] = maps_to_json(g.ifs);
      body["origin_colouring"] = cname;
    } catch (const Error& e) {
      body["warnings"].push_back(fmt::format("colouring not used: {}", e.what()));
    }
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
  StudioHosts hosts_;
  httplib::Server server_;
  int port_ = 0;
  std::atomic<bool> done_{false};
  std::mutex mutex_;   // guards inputs_ and in_flight_
  InputFiles inputs_;  // the files read: the presets opened (never saved over)
  std::map<std::string, std::shared_ptr<std::atomic<bool>>> in_flight_;  // stop flags by tab
  std::mutex upload_mutex_;
  std::unique_ptr<StudioExtras> extras_;  // jobs, fit, video, camera, superIFS
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
  cmd->add_option("--port", args->port, "Port to listen on (0: a free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--listen", args->listen,
                  "Address to listen on: the loopback only by default; another address of this "
                  "machine, or 0.0.0.0 (::) for all, lets other machines connect (with a warning; "
                  "the token is still needed)")
      ->capture_default_str();
  cmd->add_option("--folder", args->folder,
                  "Folder of source images (steal mode) and saved presets")
      ->capture_default_str();
  cmd->add_flag("--open", args->open, "Open the page in the browser (xdg-open)");
  cmd->add_option("--source", args->source,
                  "A movie to open in the Video panel, or an image to steal colours from (any "
                  "folder; the page calls it @source)");
  cmd->add_option("--camera", args->camera,
                  "A V4L2 camera (/dev/videoN) for the live filter in the Video panel");
  cmd->callback([args] {
    StopSignals signals;
    Studio studio(*args);
    studio.run();
  });
}

}  // namespace ifsfx::app
