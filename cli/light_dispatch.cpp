// SPDX-License-Identifier: Apache-2.0
#include "cli/light_dispatch.h"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "ifs/error.h"
#include "run/render_modes.h"

namespace ifsfx::app {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (auto& ch : out) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return out;
}

// A value CLI11 would take as one: not empty and not option-like ("-1,0,1,2" is a value).
bool plain_value(std::string_view value) {
  return !value.empty() &&
         (value[0] != '-' ||
          (value.size() > 1 &&
           (std::isdigit(static_cast<unsigned char>(value[1])) != 0 || value[1] == '.')));
}

// A render mode the light binary runs: one that reads no image (it has no image reader; the
// modes' table, run/render_modes.h, says which take a source).
bool reads_no_image(const std::string& mode) {
  try {
    return !render_mode_info(parse_render_mode(mode)).source;
  } catch (const Error&) {
    return false;  // an unknown mode: ifsfx-full gives the message
  }
}

}  // namespace

bool light_runs(int argc, char** argv) {
  if (argc >= 2 && std::string_view(argv[1]) == "dataset") {
    for (int i = 2; i < argc; ++i) {
      const std::string_view arg = argv[i];
      if (arg == "--") break;
      if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "--version") return false;
    }
    return true;
  }
  if (argc < 2 || std::string_view(argv[1]) != "render") return false;
  int outputs = 0, modes = 0;
  std::string_view output, mode = "measure";
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--") break;  // the rest are positional
    if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "--version") return false;
    std::string_view* value = nullptr;
    if (arg == "-o" || arg == "--output" || arg == "--mode") {
      if (i + 1 >= argc) return false;
      value = arg == "--mode" ? &mode : &output;
      *value = argv[++i];
    } else if (arg.starts_with("--output=")) {
      value = &output;
      *value = arg.substr(9);
    } else if (arg.starts_with("--mode=")) {
      value = &mode;
      *value = arg.substr(7);
    } else if (arg.starts_with("-o")) {
      value = &output;
      *value = arg.substr(2);
    } else if (arg.size() > 2 && arg[0] == '-' && arg[1] != '-' && !plain_value(arg)) {
      return false;  // a group of short flags ("-qo out.tif") or something stranger
    }
    if (value == nullptr) continue;
    if (!plain_value(*value)) return false;
    ++(value == &mode ? modes : outputs);
  }
  return outputs == 1 && modes <= 1 && lower(fs::path(output).extension().string()) == ".png" &&
         reads_no_image(std::string(mode));
}

void exec_full_binary(char** argv) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    std::fprintf(stderr, "ifsfx: cannot find the full ifsfx binary (/proc/self/exe: %s)\n",
                 ec.message().c_str());
    std::exit(1);
  }
  const fs::path installed = (self.parent_path() / IFSFX_FULL_FROM_BINDIR).lexically_normal();
  const fs::path beside = self.parent_path() / "ifsfx-full";
  const fs::path& full = ::access(installed.c_str(), X_OK) == 0 ? installed : beside;
  if (::access(full.c_str(), X_OK) != 0) {
    std::fprintf(stderr,
                 "ifsfx: cannot find %s (nor %s): the program that runs every command but "
                 "`render` to PNG; reinstall ifsfx\n",
                 installed.c_str(), beside.c_str());
    std::exit(1);
  }
  ::execv(full.c_str(), argv);
  std::fprintf(stderr, "ifsfx: cannot run %s (%s)\n", full.c_str(), std::strerror(errno));
  std::exit(1);
}

}  // namespace ifsfx::app
