// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio [PRESET] [--source IMAGE|MOVIE] [--camera /dev/videoN] [--port N] [--listen ADDR]
// [--folder DIR] [--open]`: a local web editor served by the engine (docs/studio.md). The server
// is the studio library (studio/server.h); this command parses the flags, finds the page's files,
// prints the URL (and a warning when other machines can connect), opens the browser, and stops
// the server on Ctrl-C or SIGTERM.
#include <spawn.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.h"
#include "cli/stop_signals.h"
#include "ifs/error.h"
#include "studio/server.h"

extern char** environ;

namespace ifsfx::app {
namespace {

namespace fs = std::filesystem;

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

void open_browser(const std::string& url) {
  pid_t pid = 0;
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) !=
      0)
    std::fputs("ifsfx: --open: cannot run xdg-open; open the URL above by hand\n", stderr);
}

void run_studio(ServerConfig config, bool open) {
  StopSignals signals;
  config.web = web_folder();
  Server server(std::move(config));
  const int port = server.start();
  if (!server.hosts().loopback_only())
    fmt::print(stderr,
               "ifsfx: warning: studio: listening on {} port {}: other machines can connect; "
               "whoever has the URL's token can render and read and write files in {}\n",
               server.hosts().listen(), port, server.folder().string());
  const std::string url = server.url();
  std::printf("ifsfx studio: %s\n", url.c_str());
  std::fflush(stdout);
  if (open) open_browser(url);
  // Ctrl-C or SIGTERM: cancel the renders in flight and stop listening, polled every 20 ms.
  while (!StopSignals::stop_flag() && server.running())
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  server.stop();
  if (StopSignals::stop_flag()) throw Error(ErrorKind::interrupted, "studio: interrupted");
}

}  // namespace

void add_studio_command(CLI::App& app) {
  auto config = std::make_shared<ServerConfig>();
  auto open = std::make_shared<bool>(false);
  auto folder = std::make_shared<std::string>(".");
  auto* cmd = app.add_subcommand(
      "studio",
      "A local web editor: drag the maps of an IFS and watch the picture (docs/studio.md)");
  cmd->add_option("preset", config->preset,
                  "Preset to open: a shipped name, a .toml/.ifs path, or FILE.ifs:NAME")
      ->capture_default_str();
  cmd->add_option("--port", config->port, "Port to listen on (0: a free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  cmd->add_option("--listen", config->listen,
                  "Address to listen on: the loopback only by default; another address of this "
                  "machine, or 0.0.0.0 (::) for all, lets other machines connect (with a warning; "
                  "the token is still needed)")
      ->capture_default_str();
  cmd->add_option("--folder", *folder, "Folder of source images (steal mode) and saved presets")
      ->capture_default_str();
  cmd->add_flag("--open", *open, "Open the page in the browser (xdg-open)");
  cmd->add_option("--source", config->source,
                  "A movie to open in the Video panel, or an image to steal colours from (any "
                  "folder, or relative to --folder; the page calls it @source and selects it)");
  cmd->add_option("--camera", config->camera,
                  "A V4L2 camera (/dev/videoN) for the live filter in the Video panel");
  cmd->callback([config, open, folder] {
    ServerConfig c = *config;
    c.folder = *folder;
    run_studio(std::move(c), *open);
  });
}

}  // namespace ifsfx::app
