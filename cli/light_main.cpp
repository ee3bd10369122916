// SPDX-License-Identifier: Apache-2.0
// ifsfx, the installed command: `render` to PNG and `dataset` in a binary that loads neither
// OpenImageIO nor the video stack, every other command line handed to ifsfx-full
// (cli/light_dispatch.h).
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/light_dispatch.h"
#include "cli/run_cli.h"

int main(int argc, char** argv) {
  if (!ifsfx::app::light_runs(argc, argv)) ifsfx::app::exec_full_binary(argv);
  CLI::App app{ifsfx::app::kDescription};
  app.require_subcommand(1);
  ifsfx::app::add_render_command(app);
  ifsfx::app::add_dataset_command(app);
  return ifsfx::app::run_cli(app, argc, argv);
}
