// SPDX-License-Identifier: Apache-2.0
// Which of the two ifsfx binaries runs a command line. Most of ifsfx's start-up is the dynamic
// loader binding OpenImageIO and the video stack (about 275 shared libraries; bench/README.md,
// "Start-up"), which `render` to PNG does not use. So the installed `ifsfx` is a light binary
// that links only what that needs (cli/light_main.cpp) and execs the full one, ifsfx-full, for
// everything else, before it builds any command line: the same process, arguments, exit codes,
// messages and signals, for about 5 ms more (the light binary's own start-up).
#pragma once

namespace ifsfx::app {

// Whether the light binary runs `argv` itself: `render` with one -o/--output ending in .png and
// --mode attractor, measure or tops (steal reads a source image of any format), and `dataset`
// (FractalDB datasets: PNG files of its own, docs/dataset.md); either with no --help, -h,
// --help-all or --version. A command line it cannot read with certainty (a short-flag group
// such as -qo, an option value that looks like an option) goes to the full binary, which runs
// every command line.
bool light_runs(int argc, char** argv);

// Replaces the process by the full binary with the same arguments: installed in
// LIBEXECDIR/ifsfx/ (its path relative to the light binary's folder, IFSFX_FULL_FROM_BINDIR, is
// fixed at configure time), or beside the light binary in the build tree. When neither is there,
// or exec fails, prints one line "ifsfx: cannot find PATH ..." or "ifsfx: cannot run PATH (...)"
// and exits with 1.
[[noreturn]] void exec_full_binary(char** argv);

}  // namespace ifsfx::app
