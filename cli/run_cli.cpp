// SPDX-License-Identifier: Apache-2.0
#include "cli/run_cli.h"

#include <csignal>
#include <cstdio>
#include <exception>

#include <fmt/format.h>

#include "cli/cli_errors.h"
#include "cli/stop_signals.h"
#include "ifs/error.h"

namespace ifsfx::app {
namespace {

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::parse:
    case ErrorKind::invalid_ifs:
    case ErrorKind::invalid_argument:
      return 2;
    case ErrorKind::interrupted: {
      const int signal = StopSignals::signal_number();
      return 128 + (signal > 0 ? signal : SIGINT);
    }
    default:
      return 1;
  }
}

}  // namespace

int run_cli(CLI::App& app, int argc, char** argv) {
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
    fmt::print(stderr, "ifsfx: {}\n", e.what());
    return 2;
  } catch (const Error& e) {
    fmt::print(stderr, "ifsfx: {}\n", with_flag_names(e.what()));
    return exit_code(e.kind());
  } catch (const std::exception& e) {
    fmt::print(stderr, "ifsfx: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace ifsfx::app
