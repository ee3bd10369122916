// SPDX-License-Identifier: Apache-2.0
// What both ifsfx binaries share around their commands (cli/main.cpp: every command;
// cli/light_main.cpp: `render` to PNG): the top-level description, and main()'s error handling.
#pragma once

#include <CLI/CLI.hpp>

namespace ifsfx::app {

inline constexpr const char* kDescription =
    "ifsfx: turn images and video into fractals (IFS, fractal tops, colour stealing,\n"
    "V-variable superfractals). `ifsfx COMMAND --help` for each command.";

// Parses the command line into `app`, runs the command its callback holds, and turns every error
// into a single line "ifsfx: ..." on stderr and the exit code to return from main(): 0 success,
// 1 runtime failure, 2 bad command line or bad input file, and for a run stopped by a signal
// 128 + its number, as a shell reports a process the signal killed: 130 for SIGINT (Ctrl-C), 143
// for SIGTERM.
int run_cli(CLI::App& app, int argc, char** argv);

}  // namespace ifsfx::app
