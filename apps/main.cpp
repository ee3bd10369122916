// ifsfx: an IFS and superfractal image/video filter. main() parses the command line, runs one
// subcommand, and turns every error into a single line "ifsfx: ..." on stderr and an exit code.
#include <cstdio>
#include <exception>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "apps/cli_errors.h"
#include "apps/commands.h"
#include "apps/stop_signals.h"
#include "ifs/error.h"

namespace {

// Exit codes: 0 success, 1 runtime failure, 2 bad command line or bad input file, and for a run
// stopped by a signal 128 + its number, as a shell reports a process the signal killed: 130 for
// SIGINT (Ctrl-C), 143 for SIGTERM.
int exit_code(ifsfx::ErrorKind kind) {
  switch (kind) {
    case ifsfx::ErrorKind::parse:
    case ifsfx::ErrorKind::invalid_ifs:
    case ifsfx::ErrorKind::invalid_argument:
      return 2;
    case ifsfx::ErrorKind::interrupted: {
      const int signal = ifsfx::app::StopSignals::signal_number();
      return 128 + (signal > 0 ? signal : SIGINT);
    }
    default:
      return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "ifsfx: turn images and video into fractals (IFS, fractal tops, colour stealing,\n"
      "V-variable superfractals). `ifsfx COMMAND --help` for each command."};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show the help of every command");
  app.set_version_flag("--version", ifsfx::app::version_text,
                       "Show the version, the build and the kernel level used here, and exit");
  ifsfx::app::add_presets_command(app);
  ifsfx::app::add_render_command(app);
  ifsfx::app::add_apply_command(app);
  ifsfx::app::add_fit_command(app);
  ifsfx::app::add_texture_command(app);
  ifsfx::app::add_cam_command(app);
  ifsfx::app::add_filter_command(app);
  ifsfx::app::add_info_command(app);
  ifsfx::app::add_farm_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    std::fputs(e.what(), stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::fputs(fmt::format("ifsfx: {}\n", e.what()).c_str(), stderr);
    return 2;
  } catch (const ifsfx::Error& e) {
    std::fputs(fmt::format("ifsfx: {}\n", ifsfx::app::with_flag_names(e.what())).c_str(), stderr);
    return exit_code(e.kind());
  } catch (const std::exception& e) {
    std::fputs(fmt::format("ifsfx: internal error: {}\n", e.what()).c_str(), stderr);
    return 1;
  }
  return 0;
}
